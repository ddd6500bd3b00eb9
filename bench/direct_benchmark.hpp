#pragma once
// `lfd bench direct` (docs/performance.md "Direct panel rendering"): the panel of a display
// rendered two ways from the same sweeping planes on one backend, in one process, the runs
// alternating: the quilt path (swizzle blend into the quilt, then the interlacer) and the direct
// pass (every subpixel composited at its own view offset, no quilt). Per display, scene and plane
// count: the median time after the planes (swizzle + interlace against the direct pass) and of the
// whole frame after warm-up, the quilt's memory, and the quality of both against a continuous
// reference (the panel from per-view renders at many views, nearest view per subpixel): PSNR over
// the panel for the direct panel and for the quilt path with nearest and linear view blending.
// Prints Markdown tables as rows finish; returns the figures as JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/render_benchmark.hpp"
#include "lightfield/light_field_renderer.hpp"
#include "render/swizzle_blend.hpp"

namespace lfd::bench {

struct DirectBenchOptions {
  std::vector<std::string> calibrations;  // visual.json / calibration.json files
  std::vector<SceneSource> scenes;
  std::vector<int> chunks = {64};  // N_chunk of each row (quality and time against the planes)
  int plane_scale = 1;             // P_s of every row (render::G2lfOptions::plane_scale)
  int runs = 0;                    // timed frames per side and row; 0: the backend's default
  int warmup = 1;                  // untimed frames of each side first
  int reference_views = 256;       // views of the continuous reference; 0: no quality figures
  int view_height = 512;           // view height; the width follows the display's aspect
  // The direct pass's plane sampling (the quilt path keeps the renderer's): bilinear stands in
  // for the interlacer's bilinear lookup in the quilt, which the direct pass does not have.
  render::PlaneFilter direct_filter = render::PlaneFilter::kBilinear;
  // GL: bilinear planes filtered by the texture unit (one fetch) or by hand (four texelFetch, the
  // CPU's weights): lightfield::GlRenderOptions::direct_hardware_bilinear.
  bool direct_hardware_bilinear = true;
  // GL: also time the compute direct pass walking the planes plane-major (a barrier a plane:
  // gpu::DirectPanelPass::kComputePlaneMajor) in the same rounds (docs/gpu.md "The direct panel
  // pass on the GPU").
  bool plane_major = false;
  // CPU: the direct pass's sampling loop (render/plane_samples.hpp).
  render::SampleKernel direct_kernel = render::sample_window_kernel();
  // kGaussians: G2LF planes of Gaussian scenes (SceneSource::generated = Gaussians of a generated
  // tabletop); kVoxels: V2LF planes of voxel scenes (generated = the generated voxel tabletop's
  // finest level, voxel/voxel_generator.hpp). The renderers must be of this kind.
  scene::SceneKind kind = scene::SceneKind::kGaussians;


  // InputError "direct benchmark: <field>: ..." for a value out of range.
  void check() const;
};

// `sweeping`: the G2LF renderer of a backend (its plane options are set per row); `per_view`:
// the same backend's per-view renderer, for the reference (may be null when reference_views = 0).
nlohmann::ordered_json run_direct_benchmark(lightfield::LightFieldRenderer& sweeping,
                                            lightfield::LightFieldRenderer* per_view,
                                            const DirectBenchOptions& options);

}  // namespace lfd::bench
