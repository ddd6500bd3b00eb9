#pragma once
// V2LF stage 1 on the GPU (paper section "V2LF", Alg. 1 lines 1-3 with voxels; the twin of
// voxel::bin_voxels_by_depth without splitting), in compute passes with no read-back, G2LF's
// binning (gpu/splats/gl_depth_binning.hpp) with a voxel cull in front and the octant grouping after:
//   keys      voxels with a corner in front of the reference camera, key = centre depth
//             (depth_key.glsl's signed map), value = voxel index, binned ones counted
//             (gpu/voxels/shaders/voxel_binning_keys.comp.glsl)
//   sort      GlRadixSort: binned voxels front to back, ties in index order (the CPU sorts
//             (depth, index) pairs)
//   chunks    GlDepthBinning::chunk_sorted: G2LF's cuts, chunks and layers passes, the one
//             definition of the chunk relation (render/depth_binning.hpp's twin): plane table
//   chunk_of  each voxel's chunk by index (voxel_binning_chunk_of.comp.glsl)
//   orders    each octant in view's front-to-back order (uploaded once with the scene) grouped
//             by chunk with a stable radix sort of chunk keys (one pass up to 255 planes), copied
//             to the octant's slot (voxel_binning_orders.comp.glsl): group_by_octant on the CPU
//   draws     per (plane, octant) an indirect draw of that chunk's voxels in that order, and
//             per plane the indirect dispatch of its filter and convert passes, empty past the
//             frame's plane count (voxel_binning_draws.comp.glsl)
// The scene never leaves the GPU and nothing is read back: the plane count and every draw's size
// stay on the GPU, so the CPU issues the same commands whatever the scene (docs/gpu.md, "Voxels
// on the GPU"). Membership, plane count and plane depths are the CPU's bit for bit.
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "gpu/splats/gl_depth_binning.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/compute/gl_radix_sort.hpp"
#include "gpu/voxels/gl_voxel_raster.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "render/depth_binning.hpp"
#include "render/quilt_geometry.hpp"

namespace lfd::gpu {

class GlVoxelBinning {
 public:
  GlVoxelBinning();  // needs a current context; compiles the passes

  // Bins `scene` for `ref` into at most `chunks` planes (<= table.max_planes) and writes the
  // plane table, the grouped orders (orders()) and the draws (draws(): command 8 k + octant for
  // plane k, then per plane a dispatch of `plane_groups` work groups, or none past the plane
  // count, at plane_dispatch_offset). Enqueues GPU work only; ends with the barriers the
  // raster, the per-plane passes and the swizzle need.
  void run(const GlVoxelScene& scene, const render::ReferenceCamera& ref, int chunks,
           render::ChunkBinning binning, const glm::uvec2& plane_groups, GlPlaneTable& table);
  // Byte offset in draws() of plane `plane`'s DispatchIndirectCommand.
  static size_t plane_dispatch_offset(int plane, int max_planes);

  const Buffer& orders() const { return group_values_; }  // uint voxel ids, slot s at [s n, (s + 1) n)
  const Buffer& draws() const { return draws_; }          // DrawArraysIndirect commands
  const Buffer& chunk_of() const { return chunk_of_buffer_; }  // uint plane per voxel (capacity: not binned)
  size_t bytes() const;

 private:
  void keys(const GlVoxelScene& scene, const render::Camera& camera, GlPlaneTable& table);
  void group_orders(const GlVoxelScene& scene, uint32_t octants, int max_planes, const glm::uvec2& plane_groups,
                    GlPlaneTable& table);

  Program keys_, chunk_of_, orders_, draws_pass_;
  GlDepthBinning chunking_;
  GlRadixSort sort_;
  Buffer keys_buffer_, values_, layers_, chunk_of_buffer_, group_keys_, group_sorted_, group_values_, draws_;
};

}  // namespace lfd::gpu
