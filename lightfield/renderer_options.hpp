#pragma once
// What a light-field renderer is asked for (lightfield/renderer_factory.hpp chooses the renderer
// from it): the backend (the CPU reference or OpenGL), the method (every view rendered alone, or
// the sweeping planes: G2LF for Gaussians, V2LF for voxels; docs/rendering.md, docs/voxels.md),
// the planes' options, the background, and what only the GL renderers read.
#include <cstddef>
#include <optional>
#include <string>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/voxels/gl_v2lf.hpp"
#include "interlace/direct_panel.hpp"
#include "gpu/gl/raster_path.hpp"
#include "scene/scene.hpp"
#include "render/g2lf.hpp"
#include "render/plane_samples.hpp"
#include "render/preprocess.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::lightfield {

enum class Backend { kCpu, kGl };
enum class Method { kPerView, kSweepingPlanes };

// What the backend runs on, for reports: "CPU" | "GPU".
const char* processor_name(Backend backend);

// The method's name as `lfd render --method` spells it: "per-view", "g2lf" (Gaussians' sweeping
// planes) or "v2lf" (voxels').
std::string method_name(Method method, scene::SceneKind kind);

// What only the GL renderers read.
struct GlRenderOptions {
  // How Gaussians and voxels are drawn, per view and into G2LF's and V2LF's planes: the hardware
  // raster pipeline, the compute tile rasterizer, or auto (resolved once per device and kind of
  // scene by a measurement: gpu::resolve_raster_path; docs/gpu.md "Two ways to draw Gaussians").
  gpu::RasterPath raster = gpu::RasterPath::kHardware;
  // Plane texel format; unset: the CPU precision's. RGBA16F exists only on the GPU.
  std::optional<gpu::PlaneFormat> plane_format;
  // The quilt the renderer renders into and read_quilt reads back: RGBA32F (the CPU's floats to
  // rounding) or RGBA8 (the quilt as displayed, what the benchmarks time).
  GLenum quilt_format = GL_RGBA32F;
  // Per-stage GPU timers in the stats (waits for the GPU at the end of a frame: benchmarks and
  // the viewer's frame report). The per-view renderer makes its gpu:: renderer again when it
  // changes (its timer queries are made with it).
  bool gpu_timers = false;
  // kLate: the timers (and G2LF's counts) are read a few frames late without waiting: the viewer
  // (docs/gpu.md "A frame that never waits").
  gpu::TimerReads timer_reads = gpu::TimerReads::kWait;
  // Per view: the depth key bits sorted (gpu::GlPerViewOptions::depth_key_bits; 32 exact, the
  // viewer 24: 3 radix passes instead of 4).
  int depth_key_bits = 32;
  // Per view: those bits spread over the view's visible depth range
  // (gpu::GlPerViewOptions::normalised_depth_keys; the viewer's 16 bits: 2 radix passes).
  bool normalised_depth_keys = false;
  // Per view: the blending target (gpu::GlPerViewOptions::accumulation_format): RGBA32F (the
  // CPU's to ~80 dB) or RGBA16F (half the bytes a blend: 2.5x faster on an H200 at 1M
  // Gaussians, the viewer's; docs/performance.md "The GPU table").
  GLenum per_view_accumulation_format = GL_RGBA32F;
  // The direct panel pass samples bilinear planes with the texture unit (gpu::GlDirectPanel;
  // off: four texelFetch with the CPU's weights, its exact twin).
  bool direct_hardware_bilinear = true;
  // The direct panel pass into a texture as the compute pass over panel tiles (gpu::DirectPanelPass;
  // docs/gpu.md "The direct panel pass on the GPU"); off: the fragment pass (the benchmark's other side).
  bool direct_compute = true;
  // With direct_compute: the tile walks the planes with a barrier after each (gpu::DirectPanelPass::
  // kComputePlaneMajor, the swizzle's order); what `lfd bench direct --plane-major` times beside it.
  bool direct_plane_major = false;
  size_t memory_budget_bytes = 0;  // G2LF: gpu::GlG2lfOptions::memory_budget_bytes
  size_t accumulation_budget_bytes = gpu::GlG2lfOptions{}.accumulation_budget_bytes;
};

struct RendererOptions {
  Backend backend = Backend::kCpu;
  Method method = Method::kSweepingPlanes;
  // The sweeping planes' options (G2LF's; V2LF uses all of them, adaptive_filter switching its
  // planes' low-pass filter).
  render::G2lfOptions planes;
  int split_levels = 0;  // V2LF: voxel::V2lfOptions::split_levels
  // Unset: black behind Gaussians, the scene's own background behind voxels.
  std::optional<glm::vec3> background;
  GlRenderOptions gl;
  // The direct pass's plane sampling (interlace::DirectPanelOptions::filter, bilinear unless told;
  // planes.filter is the swizzle's).
  render::PlaneFilter direct_filter = interlace::DirectPanelOptions{}.filter;
  // The CPU direct pass's sampling loop (interlace::DirectPanelOptions::kernel).
  render::SampleKernel direct_kernel = render::sample_window_kernel();

  // planes.check() and InputError "renderer options: plane_format: ..." for RGBA16F planes on
  // the CPU.
  void check() const;

  // The options of the calls each renderer wraps.
  render::RasterSettings raster_settings() const;
  voxel::VoxelRenderSettings voxel_settings() const;
  voxel::V2lfOptions v2lf() const;
  gpu::GlG2lfOptions gl_g2lf() const;
  gpu::GlV2lfOptions gl_v2lf() const;
};

}  // namespace lfd::lightfield
