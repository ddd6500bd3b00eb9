#pragma once
// A sparse-voxel scene (scene/voxel_scene.hpp) uploaded once into shader storage buffers for
// the GL voxel raster (V2LF's GPU half, docs/gpu.md "Voxels on the GPU"). std430, vec4-packed:
//   kVoxelBoxesBinding      vec4 boxes[]       (min corner x, y, z, edge length)
//   kVoxelDensitiesBinding  vec4 densities[2v] raw corner densities 0-3, 4-7 (corner i at
//                           (x, y, z) = bits (2, 1, 0) of i, as VoxelScene)
//   kSceneShBinding         vec4 sh[]          sh_vec4_stride() vec4s per voxel, the layout of
//                           GlScene's SH so gpu/splats/shaders/sh_color.glsl reads both
//   kVoxelOrderBinding      uint order[8 v]    the eight front-to-back orders (voxel/ray_order.hpp),
//                           order o at [o v, (o + 1) v): octant o's rays visit voxels in it
// (binding points: gpu/splats/shaders/frame_io.h)
// The eight orders depend on the scene only (not the camera), so they are sorted once here on
// the CPU and kept there too: V2LF groups each order by chunk per frame (gpu/gl_voxel_renderer.hpp).
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "render/camera.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::gpu {

// GPU bytes per voxel of the scene buffers at `sh_degree`.
size_t voxel_scene_bytes_per_voxel(int sh_degree);

// Throws InputError (one line with the numbers) when `voxels` exceed 32-bit indices, a storage
// buffer would pass GL_MAX_SHADER_STORAGE_BLOCK_SIZE, or the scene the free memory the driver reports.
void check_voxel_scene_fits(size_t voxels, int sh_degree, const GlInfo& info);

class GlVoxelScene {
 public:
  // Needs a current context; `scene` is copied (the GPU buffers and the CPU-side orders).
  GlVoxelScene(const scene::VoxelScene& scene, const GlInfo& info);

  const scene::VoxelScene& scene() const { return scene_; }
  size_t size() const { return scene_.size(); }
  size_t bytes() const;
  // Octant o's front-to-back order (voxel indices), as uploaded.
  const std::vector<uint32_t>& order(int octant) const { return orders_[size_t(octant)]; }
  const Buffer& order_buffer() const { return order_; }
  const Buffer& boxes() const { return boxes_; }  // min xyz, edge per voxel
  const Buffer& densities() const { return densities_; }
  const Buffer& sh() const { return sh_; }

 private:
  scene::VoxelScene scene_;
  std::array<std::vector<uint32_t>, 8> orders_;
  Buffer boxes_, densities_, sh_, order_;
};

// The octants whose rays pass through some pixel of `camera`'s image (a superset: per axis,
// the signs the world direction's component takes at the image's corner pixels, since it is
// linear in the pixel position), as a bit mask (bit o = octant o).
uint32_t octants_in_view(const render::Camera& camera);

}  // namespace lfd::gpu
