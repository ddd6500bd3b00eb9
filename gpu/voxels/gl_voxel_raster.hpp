#pragma once
// SVRaster's forward pass on the GPU (docs/gpu.md "Voxels on the GPU"): the GL twin of voxel/voxel_rasterizer.hpp's
// rasterize_voxels_exact. Per octant of ray directions the image holds (octants_in_view), one
// instanced draw of that octant's front-to-back order (gpu/voxels/shaders/voxel_raster.*.glsl): a
// quad per voxel over its projected box, the slab test and density samples per fragment,
// fragments of rays of another octant discarded. Draw order is blend order in GL, so every
// pixel composites its voxels in its own octant's order, as the CPU sorts them per pixel.
//
// Targets are GlSplatRaster's: (C, T) in a float framebuffer region, blended front to back
// (C += c alpha T, T *= 1 - alpha), the background composited after. Not exact where the CPU
// stops a ray (T < 1e-4): fixed blending cannot read T, so later voxels still add at most
// 1e-4 max(colour) there (the splat raster's note, gl_splat_raster.hpp, with 1e-4 for 0.01).
#include <array>
#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/gl_splat_raster.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "render/camera.hpp"

namespace lfd::gpu {

// Entries [offset, offset + count) of an order buffer: one octant's voxels, front to back.
struct VoxelOrderRange {
  uint32_t offset = 0;
  uint32_t count = 0;
};
using VoxelOrderRanges = std::array<VoxelOrderRange, 8>;  // per octant; count 0: not drawn

class GlVoxelRaster {
 public:
  GlVoxelRaster();  // needs a current context

  // Draws the voxels of `ranges` (indices into `order`, a uint buffer) of `scene`, seen by
  // `camera` (its size is target.image_size), into `target`, SH seen from `sh_origin`. Octants
  // no pixel's ray takes are skipped. The target is not cleared.
  void draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
            const Buffer& order, const VoxelOrderRanges& ranges, const SplatRasterTarget& target) const;
  // V2LF's planes (gpu/voxels/gl_voxel_binning.hpp): the view's uniforms and buffers once a frame
  // (begin_indirect), then per plane its indirect draws (draw_indirect: command 8 plane + octant
  // of `draws`, base instance = where its voxels begin in `order`; sizes and offsets stay on the
  // GPU), the octants no pixel's ray takes skipped. In between, passes may run that leave storage
  // bindings of the voxel scene and draws (gpu/splats/shaders/frame_io.h) and the draw-indirect buffer
  // alone (the planes' filter and convert passes).
  void begin_indirect(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                      const Buffer& order, const Buffer& draws, const SplatRasterTarget& target);
  void draw_indirect(int plane, const SplatRasterTarget& target) const;
  // Every voxel of the scene, in the scene's own orders.
  void draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
            const SplatRasterTarget& target) const;

 private:
  // The view's uniforms and the scene's buffers; returns the octants in view.
  uint32_t set_view(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                    const Buffer& order, const SplatRasterTarget& target) const;
  // The target's state, then `issue(octant)` per octant of `octants`.
  void draw_octants(uint32_t octants, const SplatRasterTarget& target,
                    const std::function<void(int octant)>& issue) const;

  Program program_;
  Buffer no_draws_;  // at the draws' point for the direct draws, which read no command
  VertexArray vertex_array_;
  uint32_t indirect_octants_ = 0;  // begin_indirect's view
};

}  // namespace lfd::gpu
