#pragma once
// `lfd bench gpu-frame`: the GL frame itself, both sides of each GPU-side change in one run
// (docs/gpu.md "A frame that never waits", docs/performance.md): G2LF and per view on one
// headless context, each variant timed the same way.
//   - timers waited for (each frame reads its stage times at once, the CPU waiting for the
//     GPU: the old frame) against timers read late (gpu/gl/gl_frame_ring.hpp), frames issued back
//     to back and finished once per batch: the wall time per frame of a pipelined loop;
//   - the G2LF swizzle with 1 view per invocation (the old mapping) against several;
//   - G2LF's planes drawn in batches through RGBA32F accumulation (RGBA8 planes) against one
//     layered draw straight into RGBA16F planes (and into RGBA8);
//   - G2LF's swizzle with its views x planes table and without; bilinear by hand (the CPU's
//     weights) against the texture unit's;
//   - per view: RGBA32F blending targets against RGBA16F (half the bytes a blend), and the
//     depth sorted by all 32 bits of its key (4 radix passes) against the default 24 (3);
//   - with sort_only (--sort-only) instead: the sort over all N against the visible (binned)
//     Gaussians only, for G2LF's binning and per view, and per view float keys against 16 bits
//     normalised to the visible range, the variants interleaved round by round.
//   - --raster compute (GpuFrameOptions::rasters): G2LF's planes and the per-view quilt drawn by
//     the compute tile rasterizer beside the hardware rows, stage times from the same timers;
//   - V2LF on a generated voxel scene: the voxels binned on the CPU and uploaded every frame
//     against binned on the GPU (gpu/voxels/gl_voxel_binning.hpp), runs alternated.
// G2LF's variants each on a renderer of its own, their runs interleaved (a drifting load weighs
// on all alike). Medians of --runs after --warmup; on llvmpipe the figures say how the CPU emulation responds,
// not what a GPU would.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/gl_vs_cpu_benchmark.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/raster_path.hpp"

namespace lfd::bench {

struct GpuFrameOptions {
  int views = 45;
  int chunks = 64;
  int runs = 5, warmup = 1;
  int batch = 4;                          // frames per pipelined batch
  std::vector<int> swizzle_views{1, 4, 8};  // G2LF swizzle variants
  bool sort_only = false;                   // the sort rows instead of the others
  int voxel_level = 7;  // the generated voxel tabletop of the V2LF rows (voxel/voxel_generator.hpp); 0: none
  // G2LF plane raster variants: "batched" (RGBA8 through accumulation), "layered" (RGBA16F),
  // "layered-rgba8" (blended in RGBA8).
  std::vector<std::string> planes{"batched", "layered", "layered-rgba8"};
  std::vector<bool> swizzle_table{false, true};       // the views x planes table off / on
  std::vector<bool> hardware_bilinear{false, true};   // bilinear rows: by hand / texture unit
  bool per_view = true;                               // the per-view rows (slow on llvmpipe)
  // How the Gaussians are drawn (docs/gpu.md "Two ways to draw Gaussians"): kHardware, the
  // variants above; kCompute, G2LF's planes and the per-view quilt by the compute tile rasterizer
  // (timers waited for, and G2LF with timers read late), each with its GPU stage times.
  std::vector<gpu::RasterPath> rasters{gpu::RasterPath::kHardware, gpu::RasterPath::kCompute};
};

struct GpuFrameRow {
  std::string method;   // "G2LF N=64", "per view" or "V2LF N=64"
  std::string variant;  // what differs between rows of one method
  double frame_s = 0;   // median wall time per frame
  double binning_s = 0, planes_s = 0, swizzle_s = 0, raster_s = 0;  // median GPU stage times (0: not timed)
  double sort_s = 0;  // per view: the sort's share of raster_s
  int runs = 0;
};

std::vector<GpuFrameRow> run_gpu_frame(const GlVsCpuScene& scene, const GpuFrameOptions& options,
                                       const gpu::GlInfo& info);
std::string gpu_frame_table(const std::vector<GpuFrameRow>& rows);
nlohmann::ordered_json gpu_frame_json(const std::vector<GpuFrameRow>& rows);

}  // namespace lfd::bench
