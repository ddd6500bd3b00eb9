#pragma once
// SVRaster's front-to-back order without a per-ray sort: octree leaves sorted by their octree
// path (Morton order, child index (x, y, z) = bits (2, 1, 0) per level) visit every ray with
// non-negative direction components front to back, because such a ray can only move to cells
// whose index is at least as large on every axis. Flipping the path's axis bits where the ray
// direction is negative (path XOR the direction's sign octant, repeated over the voxel's levels)
// gives the other seven orders: eight orders per scene, independent of the camera.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/voxel_scene.hpp"

namespace lfd::voxel {

// Bit 2 = x, bit 1 = y, bit 0 = z set where the direction's component is negative.
int direction_octant(const glm::vec3& direction);

class RayOrder {
 public:
  explicit RayOrder(const scene::VoxelScene& scene);
  // Sorting by this key (ascending) is front to back for a ray of octant `octant`.
  uint64_t key(uint32_t voxel, int octant) const {
    return path_[voxel] ^ level_octant_mask_[level_[voxel]][size_t(octant)];
  }

 private:
  std::vector<uint64_t> path_;  // octree path padded to scene::kMaxOctreeLevel levels (3 bits each)
  std::vector<uint8_t> level_;
  std::array<std::array<uint64_t, 8>, scene::kMaxOctreeLevel + 1> level_octant_mask_{};
};

}  // namespace lfd::voxel
