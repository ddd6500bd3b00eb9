#include "voxel/ray_order.hpp"

namespace lfd::voxel {

int direction_octant(const glm::vec3& d) {
  return (d.x < 0.0f ? 4 : 0) | (d.y < 0.0f ? 2 : 0) | (d.z < 0.0f ? 1 : 0);
}

namespace {

// Interleaves the voxel's coordinates into its path, root level in the highest bits, then pads
// to the deepest level so leaves of different levels compare by position.
uint64_t padded_path(const glm::u32vec3& index, int level) {
  uint64_t path = 0;
  for (int l = level - 1; l >= 0; --l) {
    const uint64_t child = ((index.x >> l) & 1u) << 2 | ((index.y >> l) & 1u) << 1 | ((index.z >> l) & 1u);
    path = path << 3 | child;
  }
  return path << (3 * (scene::kMaxOctreeLevel - level));
}

}  // namespace

RayOrder::RayOrder(const scene::VoxelScene& scene) : path_(scene.size()), level_(scene.level) {
  for (size_t i = 0; i < scene.size(); ++i) path_[i] = padded_path(scene.octree_index[i], scene.level[i]);
  for (int level = 0; level <= scene::kMaxOctreeLevel; ++level)
    for (int octant = 0; octant < 8; ++octant) {
      uint64_t mask = 0;
      for (int l = 0; l < level; ++l) mask = mask << 3 | uint64_t(octant);
      level_octant_mask_[size_t(level)][size_t(octant)] = mask << (3 * (scene::kMaxOctreeLevel - level));
    }
}

}  // namespace lfd::voxel
