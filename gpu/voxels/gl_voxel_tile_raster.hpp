#pragma once
// SVRaster's forward pass as a compute tile rasterizer (docs/gpu.md "Voxels on the
// GPU"), the twin of GlVoxelRaster for devices where few SMs run the raster pipeline (H100/H200):
//   keys    one invocation per item, an item being a voxel of a run: a stretch of an octant's
//           front-to-back order seen in one image (gpu/voxels/shaders/voxel_tile_keys.comp.glsl): its
//           footprint's tiles whose rays can take that octant, one key (run | tile) each. A
//           quilt's views are runs too (one per octant in each view), so all views of a pass go in
//           one count, scan, emit and sort; V2LF's planes: (plane | run | tile)
//   sort    GlTileKeys: scan, stable radix sort by slot, per-slot ranges, the non-empty slots;
//           stable, so a slot keeps its octant's front-to-back order
//   march   one work group per non-empty slot (voxel_tile_march.comp.glsl): every pixel whose ray
//           takes the slot's octant composites the slot's voxels front to back with the CPU's
//           rules (gpu/voxels/shaders/voxel_ray.glsl, shared with the raster pipeline's fragments) and
//           stops at T < 1e-4, as voxel::rasterize_voxels_exact does
// Targets are RGBA32F images holding (C, T) (cleared to (0, 0, 0, 1)); the pass composites over
// what they hold, as the raster pipeline's front-to-back blend does.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/gl_program.hpp"
#include "gpu/compute/gl_key_capacity.hpp"
#include "gpu/compute/gl_tile_keys.hpp"
#include "gpu/voxels/gl_voxel_raster.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "gpu/voxels/shaders/voxel_tile_io.h"
#include "render/camera.hpp"

namespace lfd::gpu {

class GlVoxelTileRaster {
 public:
  GlVoxelTileRaster();  // needs a current context; compiles the passes

  // Every camera of `cameras` (one image size W x H), SH seen from each camera's position, into
  // its cell of `target` (GL_RGBA32F): view i at ((i % cols) W, (i / cols) H), rows bottom-up.
  // One pass (one sort, one indirect dispatch) when the items' counts fit the largest storage
  // block (pass_limit), else as few passes as fit. Octants no pixel's ray takes are skipped.
  // Keys go into buffers of the capacity kept from frame to frame; a pass whose keys outgrew it
  // marches nothing, and after every pass is issued the totals are read once and those passes
  // drawn again with it grown (GlKeyCapacity; docs/gpu.md "Memory and passes"), in two halves
  // when their keys outgrow the pass limit itself.
  void render_views(const GlVoxelScene& scene, std::span<const render::Camera> cameras, const Texture& target,
                    int cols);
  // The voxels of `ranges` (indices into `order`) of `scene`, seen by `camera`, SH seen from
  // `sh_origin`, into `target` (GL_RGBA32F) at `origin` (the view's bottom-left texel; the view is
  // camera.width x camera.height texels, rows bottom-up). V2LF's CPU-binned planes: a pass each.
  void render_view(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                   const Buffer& order, const VoxelOrderRanges& ranges, const Texture& target, glm::ivec2 origin);
  // V2LF's planes binned on the GPU (gpu/voxels/gl_voxel_binning.hpp): the keys of every plane at once
  // from its grouped orders (`orders`, the octants in view's slots of scene.size() entries each)
  // and its chunk-of buffer (planes >= plane_capacity: not binned), one sort a frame (begin_planes);
  // then per plane its run of slots into `target` (render_plane; the plane's image is `camera`'s).
  void begin_planes(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                    const Buffer& orders, const Buffer& chunk_of, int plane_capacity);
  void render_plane(int plane, const Texture& target);
  // After a frame's planes (render_view a plane, or begin_planes and render_plane): the one read
  // of their key totals. True when a pass's keys outgrew the capacity (it marched nothing; the
  // capacity is grown now): the caller draws the frame's planes again.
  bool planes_outgrew_capacity();

  // The largest buffer one pass may bind, in bytes (the items' counts, the keys, the values):
  // 0 (the default) is GL_MAX_SHADER_STORAGE_BLOCK_SIZE. Smaller values split render_views into
  // more passes (the tests' way to check that passes do not change the image). The same unit and
  // default as GlSplatTileRaster::set_pass_limit.
  void set_pass_limit(size_t bytes) { pass_limit_ = bytes; }
  size_t pass_limit() const;
  // Keys the key buffers hold: kept from frame to frame, first a key an item, grown to a quarter
  // over a frame's largest total when a pass's keys did not fit. Setting it (tests) starts from
  // another capacity.
  void set_key_capacity(uint32_t keys) { capacity_.set_keys(keys); }
  uint32_t key_capacity() const { return capacity_.keys(); }
  // Passes of the last render_views or planes drawn again because their keys outgrew the capacity.
  int redrawn_passes() const { return redrawn_; }
  // Passes (sorts and marches) the last render_views took, and the items and keys they held.
  int passes() const { return passes_; }
  uint64_t items() const { return items_; }
  uint64_t keys() const { return keys_total_; }
  size_t bytes() const { return keys_.bytes() + views_.bytes() + runs_.bytes(); }

 private:
  // A run of items: `count` voxels from order[order_offset] of `octant`'s order, in image `image`.
  struct Run {
    uint32_t image = 0, octant = 0, order_offset = 0, count = 0;
  };
  // Consecutive views [first, first + count) of render_views, and their items.
  struct ViewPass {
    size_t first = 0, count = 0;
    uint64_t items = 0;
  };
  // Uploads the runs, counts, scans, writes and sorts the keys of their voxels (per plane when
  // chunk_of is given) for images of image_size whose cameras are in views_, into buffers of the
  // kept capacity, and records the key total as pass `pass` (GlKeyCapacity); nothing is read
  // back. False when no item has a key to look for (nothing to march).
  bool make_keys(const GlVoxelScene& scene, glm::ivec2 image_size, std::span<const Run> runs, const Buffer& order,
                 const Buffer* chunk_of, int plane_capacity, uint32_t pass);
  // One pass of render_views, its keys' total recorded as pass `pass`.
  void render_view_pass(const GlVoxelScene& scene, std::span<const render::Camera> cameras, const ViewPass& views,
                        uint32_t pass, const Texture& target, int cols);
  // The march over the work list (slot_run 0) or over slots [slot_base, slot_base + slot_run),
  // image i into the cell at origin + (i % cols, i / cols) * image size; nothing when the keys
  // outgrew the capacity (the march reads the total on the GPU).
  void march(const Texture& target, glm::ivec2 origin, int cols, int images, uint32_t slot_base, uint32_t slot_run);
  // Uploads the cameras' views (SH from sh_origin, or each camera's position when null).
  void upload_views(std::span<const render::Camera> cameras, const glm::vec3* sh_origin);

  Program count_, emit_, count_planes_, emit_planes_, march_;
  GlTileKeys keys_;
  GlKeyCapacity capacity_;
  Buffer views_, runs_;
  // The images of the keys made last (march's uniforms) and whether begin_planes made them.
  const GlVoxelScene* scene_ = nullptr;
  glm::ivec2 image_size_{0};
  glm::ivec2 tile_grid_{0};
  int run_count_ = 0;
  bool planes_ready_ = false;
  uint32_t plane_passes_ = 0;  // passes of the frame's planes so far (planes_outgrew_capacity reads them)
  size_t pass_limit_ = 0;
  // The device's largest storage block (or LFD_GL_LIMITS' lower one), read once at construction:
  // a GL query a frame would be a round trip on some drivers.
  size_t device_pass_limit_ = 0;
  int passes_ = 0, redrawn_ = 0;
  uint64_t items_ = 0, keys_total_ = 0;
};

// The runs' camera record (VoxelTileView, gpu/voxels/shaders/voxel_tile_io.h) of `camera`, SH seen from
// `sh_origin`.
VoxelTileView voxel_tile_view(const render::Camera& camera, const glm::vec3& sh_origin);

}  // namespace lfd::gpu
