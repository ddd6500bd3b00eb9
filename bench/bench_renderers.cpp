#include "bench/bench_renderers.hpp"

#include "lightfield/renderer_factory.hpp"
#include "util/error.hpp"

namespace lfd::bench {

BenchRenderers make_bench_renderers(const std::string& backend, scene::SceneKind kind, gpu::RasterPath raster) {
  lightfield::RendererOptions options;
  if (backend == "gl")
    options.backend = lightfield::Backend::kGl;
  else if (backend != "cpu")
    throw_input_error("--backend: '{}' is neither cpu nor gl", backend);
  options.gl.quilt_format = GL_RGBA8;
  options.gl.raster = raster;
  // V2LF bins on the GPU: its plane and binned counts (the table's figures) come with timed
  // frames, read when the frame ends (gpu::GlV2lfStats).
  options.gl.gpu_timers = kind == scene::SceneKind::kVoxels;
  const std::shared_ptr<lightfield::GlDevice> device = lightfield::open_device(options.backend);
  BenchRenderers renderers;
  options.method = lightfield::Method::kPerView;
  renderers.per_view = lightfield::make_renderer(options, kind, device);
  options.method = lightfield::Method::kSweepingPlanes;
  renderers.sweeping = lightfield::make_renderer(options, kind, device);
  return renderers;
}

}  // namespace lfd::bench
