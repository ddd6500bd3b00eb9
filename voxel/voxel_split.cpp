#include "voxel/voxel_split.hpp"

#include <algorithm>
#include <stdexcept>

namespace lfd::voxel {

size_t append_children(const scene::VoxelScene& scene, size_t i, scene::VoxelScene& out) {
  if (scene.level[i] >= scene::kMaxOctreeLevel) throw std::logic_error("append_children: voxel at the deepest level");
  // Copies first: `out` may be `scene`, whose arrays resize() reallocates.
  const glm::u32vec3 index = scene.octree_index[i];
  const uint8_t level = scene.level[i];
  const std::array<float, 8> parent = scene.corner_density[i];
  const size_t coeffs = size_t(scene.sh_coeffs()) * 3;
  const std::vector<float> sh(scene.voxel_sh(i), scene.voxel_sh(i) + coeffs);
  const size_t first = out.size();
  out.resize(first + 8);
  for (uint32_t c = 0; c < 8; ++c) {
    const glm::u32vec3 bit((c >> 2) & 1u, (c >> 1) & 1u, c & 1u);
    const size_t j = first + c;
    out.octree_index[j] = 2u * index + bit;
    out.level[j] = uint8_t(level + 1);
    // Child corner k lies at (bit + corner bit of k) / 2 in the parent's local coordinates.
    for (uint32_t k = 0; k < 8; ++k) {
      const glm::vec3 corner(float((k >> 2) & 1u), float((k >> 1) & 1u), float(k & 1u));
      out.corner_density[j][k] = scene::trilinear(parent, 0.5f * (glm::vec3(bit) + corner));
    }
    std::copy(sh.begin(), sh.end(), out.voxel_sh(j));
  }
  return first;
}

float raw_density_at(const scene::VoxelScene& scene, size_t i, const glm::vec3& p) {
  const glm::vec3 t = glm::clamp((p - scene.voxel_min(i)) / scene.voxel_size(i), 0.0f, 1.0f);
  return scene::trilinear(scene.corner_density[i], t);
}

}  // namespace lfd::voxel
