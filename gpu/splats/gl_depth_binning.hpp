#pragma once
// G2LF stage 1 on the GPU (paper Alg. 1 lines 1-3; the twin of render/depth_binning.hpp), in
// compute passes with no read-back:
//   keys    cull to the reference frustum (centre z > 0.2, |ndc| <= 1.3), key = reference depth,
//           value = Gaussian index, binned ones counted (gpu/splats/shaders/binning_keys.comp.glsl)
//   sort    GlRadixSort: binned Gaussians first, front to back, depth ties in index order (the
//           CPU sorts (depth, index) pairs: the same order); with binned_only its first pass
//           drops the others (stably) and the later three run over the binned ones only
//   cuts    count quantiles n k / K, and for kMixed the cuts uniform in base-camera disparity
//           (binning_cuts.comp.glsl)
//   chunks  merge the cuts, drop empty chunks, plane table: count, first splat and d_k = median
//           reference depth + D_forward_eff of each plane (binning_chunks.comp.glsl)
//   layers  the plane of each sorted binned splat, for gl_Layer (binning_layers.comp.glsl)
// Membership and plane depths are the CPU's: the depths are computed with the CPU's operations
// (no fused multiply-adds) and the sort is stable. Inside a chunk the CPU keeps scene order
// while here members stay in depth order; the rasterizer sorts by depth with index ties either
// way, so the planes do not change.
#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/compute/gl_radix_sort.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "render/depth_binning.hpp"
#include "render/quilt_geometry.hpp"

namespace lfd::gpu {

// How sort keys hold depths (gpu/splats/shaders/depth_key.glsl): float bits (positive depths, G2LF's)
// or the order-preserving map of any float (V2LF's voxel centres, gpu/voxels/gl_voxel_binning.hpp).
enum class DepthKeys { kPositive, kSigned };

class GlDepthBinning {
 public:
  // Needs a current context; compiles the passes for `keys`.
  explicit GlDepthBinning(DepthKeys keys = DepthKeys::kPositive);

  // Bins `scene` for `ref` into at most `chunks` planes (<= table.max_planes):
  //   keys, values  grown to the scene; end sorted, the binned Gaussians first (with
  //                 binned_only, what follows them is stale)
  //   layers        grown to the scene; layers[i] = plane of sorted splat i < splats_binned
  //   table         plane count, binned count, d_k and first splat per plane
  //   draw          (optional) a DrawArraysIndirect whose instance count becomes the binned count
  // Enqueues GPU work only; ends with the barriers the raster, the swizzle and read-backs need.
  void run(const GlScene& scene, const render::ReferenceCamera& ref, int chunks,
           render::ChunkBinning binning, GlRadixSort& sort, Buffer& keys, Buffer& values,
           Buffer& layers, GlPlaneTable& table, const Buffer* draw = nullptr, bool binned_only = true);

  // The passes after the sort (cuts, chunks, layers) for any primitives (V2LF's voxels): `keys`
  // sorted, the binned ones (table.splats_binned of them, counted on the GPU) first, as this
  // binning's DepthKeys; `count` keys in all. Writes layers, the table and `draw` as run().
  void chunk_sorted(const render::ReferenceCamera& ref, int chunks, render::ChunkBinning binning,
                    const Buffer& keys, size_t count, Buffer& layers, GlPlaneTable& table,
                    const Buffer* draw = nullptr);

 private:
  Program keys_, cuts_, chunks_, layers_;
  Buffer cut_positions_, unused_draw_;
};

}  // namespace lfd::gpu
