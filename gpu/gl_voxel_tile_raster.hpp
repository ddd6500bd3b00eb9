#pragma once
// SVRaster's forward pass as a compute tile rasterizer (issue #33; docs/gpu.md "Voxels on the
// GPU"), the twin of GlVoxelRaster for devices where few SMs run the raster pipeline (H100/H200):
//   keys    one invocation per voxel of each octant range drawn (gpu/shaders/voxel_tile_keys.comp.glsl):
//           its footprint's tiles whose rays can take that octant, one key (image | octant | tile)
//           each (image: V2LF's plane; the octants in view only)
//   sort    GlTileKeys: scan, stable radix sort by slot, per-slot ranges, the non-empty slots;
//           stable, so a slot keeps its octant's front-to-back order
//   march   one work group per non-empty slot (voxel_tile_march.comp.glsl): every pixel whose ray
//           takes the slot's octant composites the slot's voxels front to back with the CPU's
//           rules (gpu/shaders/voxel_ray.glsl, shared with the raster pipeline's fragments) and
//           stops at T < 1e-4, as voxel::rasterize_voxels_exact does
// Targets are RGBA32F images holding (C, T) (cleared to (0, 0, 0, 1)); the pass composites over
// what they hold, as the raster pipeline's front-to-back blend does.
#include <array>

#include <glm/glm.hpp>

#include "gpu/gl_objects.hpp"
#include "gpu/gl_program.hpp"
#include "gpu/gl_tile_keys.hpp"
#include "gpu/gl_voxel_raster.hpp"
#include "gpu/gl_voxel_scene.hpp"
#include "render/camera.hpp"

namespace lfd::gpu {

class GlVoxelTileRaster {
 public:
  GlVoxelTileRaster();  // needs a current context; compiles the passes

  // The voxels of `ranges` (indices into `order`) of `scene`, seen by `camera`, SH seen from
  // `sh_origin`, into `target` (GL_RGBA32F) at `origin` (the view's bottom-left texel; the view is
  // camera.width x camera.height texels, rows bottom-up). Octants no pixel's ray takes are skipped.
  void draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
            const Buffer& order, const VoxelOrderRanges& ranges, const Texture& target, glm::ivec2 origin);
  // Every voxel of the scene, in the scene's own orders.
  void draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
            const Texture& target, glm::ivec2 origin);
  // V2LF's planes binned on the GPU (gpu/gl_voxel_binning.hpp): the keys of every plane at once
  // from its grouped orders (`orders`, the octants in view's slots of scene.size() entries each)
  // and its chunk-of buffer (planes >= plane_capacity: not binned), one sort a frame (begin_planes);
  // then per plane its run of slots into `target` (draw_plane; the plane's image is `camera`'s).
  void begin_planes(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                    const Buffer& orders, const Buffer& chunk_of, int plane_capacity);
  void draw_plane(int plane, const Texture& target);

  size_t bytes() const { return keys_.bytes(); }

 private:
  // Counts, scans, writes and sorts the keys of `ranges`' voxels (per plane when chunk_of is
  // given); false when there are none.
  bool make_keys(const GlVoxelScene& scene, const render::Camera& camera, const Buffer& order,
                 const VoxelOrderRanges& ranges, const Buffer* chunk_of, int plane_capacity);
  // The march over the work list (slot_run 0) or over slots [slot_base, slot_base + slot_run).
  void march(const Texture& target, glm::ivec2 origin, uint32_t slot_base, uint32_t slot_run);

  Program count_, emit_, count_planes_, emit_planes_, march_;
  GlTileKeys keys_;
  // The view of the keys made last (march's uniforms) and whether begin_planes made them.
  const GlVoxelScene* scene_ = nullptr;
  render::Camera camera_;
  glm::ivec2 tile_grid_{0};
  int range_count_ = 0;                 // the octants drawn: an image's slots are range_count_ * tiles
  std::array<GLint, 8> range_octant_{};
  bool planes_ready_ = false;
};

}  // namespace lfd::gpu
