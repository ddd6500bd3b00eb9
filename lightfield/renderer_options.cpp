#include "lightfield/renderer_options.hpp"

#include "gpu/probes/gl_raster_probe.hpp"
#include "util/error.hpp"

namespace lfd::lightfield {

const char* processor_name(Backend backend) { return backend == Backend::kGl ? "GPU" : "CPU"; }

std::string method_name(Method method, scene::SceneKind kind) {
  if (method == Method::kPerView) return "per-view";
  return kind == scene::SceneKind::kVoxels ? "v2lf" : "g2lf";
}

void RendererOptions::check() const {
  planes.check();
  if (gl.plane_format == gpu::PlaneFormat::kRgba16f && backend == Backend::kCpu)
    throw_input_error("renderer options: plane_format: RGBA16F planes need the GL backend; the CPU stores u8 or f32");
}

render::RasterSettings RendererOptions::raster_settings() const {
  render::RasterSettings settings;
  if (background) settings.background = *background;
  return settings;
}

voxel::VoxelRenderSettings RendererOptions::voxel_settings() const {
  voxel::VoxelRenderSettings settings;
  settings.background = background;
  return settings;
}

voxel::V2lfOptions RendererOptions::v2lf() const {
  voxel::V2lfOptions o;
  o.planes = planes;
  o.split_levels = split_levels;
  return o;
}

gpu::GlG2lfOptions RendererOptions::gl_g2lf() const {
  gpu::GlG2lfOptions o;
  o.g2lf = planes;
  o.plane_format = gl.plane_format;
  o.raster = gpu::resolve_raster_path(gl.raster);  // auto: measured once per process
  o.gpu_timers = gl.gpu_timers;
  o.timer_reads = gl.timer_reads;
  o.memory_budget_bytes = gl.memory_budget_bytes;
  o.accumulation_budget_bytes = gl.accumulation_budget_bytes;
  return o;
}

gpu::GlV2lfOptions RendererOptions::gl_v2lf() const {
  gpu::GlV2lfOptions o;
  o.v2lf = v2lf();
  o.plane_format = gl.plane_format;
  o.gpu_timers = gl.gpu_timers;
  o.timer_reads = gl.timer_reads;
  o.raster = gpu::resolve_raster_path(gl.raster, gpu::RasterSubject::kVoxels);  // auto: a voxel probe, once
  return o;
}

}  // namespace lfd::lightfield
