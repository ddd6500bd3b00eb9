#include "scene/voxel_scene.hpp"

#include <cmath>
#include <string>

#include "util/error.hpp"

namespace lfd::scene {

void VoxelScene::resize(size_t count) {
  octree_index.resize(count);
  level.resize(count);
  corner_density.resize(count);
  sh.resize(count * size_t(sh_coeffs()) * 3);
}

float VoxelScene::voxel_size(size_t i) const { return std::ldexp(scene_extent, -int(level[i])); }

glm::vec3 VoxelScene::voxel_min(size_t i) const {
  return scene_center - 0.5f * scene_extent + glm::vec3(octree_index[i]) * voxel_size(i);
}

glm::vec3 VoxelScene::voxel_center(size_t i) const { return voxel_min(i) + 0.5f * voxel_size(i); }

float exp_linear_11(float x) {
  // ln(1.1): exp(x / 1.1 - 1 + ln 1.1) = 1.1 exp(x / 1.1 - 1).
  constexpr float kLn11 = 0.09531017980432493f;
  return x > 1.1f ? x : std::exp(x / 1.1f - 1.0f + kLn11);
}

float inverse_exp_linear_11(float density) {
  constexpr float kLn11 = 0.09531017980432493f;
  return density > 1.1f ? density : 1.1f * (std::log(density) + 1.0f - kLn11);
}

float trilinear(const std::array<float, 8>& c, const glm::vec3& t) {
  float sum = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const float wx = (i & 4) ? t.x : 1.0f - t.x;
    const float wy = (i & 2) ? t.y : 1.0f - t.y;
    const float wz = (i & 1) ? t.z : 1.0f - t.z;
    sum += wx * wy * wz * c[size_t(i)];
  }
  return sum;
}

void check_voxel_scene(const VoxelScene& s, const std::string& name) {
  const auto finite3 = [](const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  require_field(finite3(s.scene_center), name, "scene_center", "must be finite");
  require_field(std::isfinite(s.scene_extent) && s.scene_extent > 0.0f, name, "scene_extent",
                "must be positive and finite");
  require_field(s.sh_degree >= 0 && s.sh_degree <= 3, name, "sh_degree", "must be 0-3");
  require_field(std::isfinite(s.supersampling) && s.supersampling >= 1.0f && s.supersampling <= 4.0f,
                name, "supersampling", "must lie in [1, 4]");
  require_field(s.samples_per_voxel >= 1 && s.samples_per_voxel <= 64, name, "samples_per_voxel",
                "must lie in 1..64");
  require_field(finite3(s.background), name, "background", "must be finite");
  const size_t n = s.size();
  require_field(s.octree_index.size() == n && s.corner_density.size() == n &&
                    s.sh.size() == n * size_t(s.sh_coeffs()) * 3,
                name, "voxels", "per-voxel arrays differ in length");
  for (size_t i = 0; i < n; ++i) {
    const int level = s.level[i];
    if (level > kMaxOctreeLevel)
      throw_input_error("{}: voxel {}: level {} is above {}", name, i, level, kMaxOctreeLevel);
    const uint32_t cells = uint32_t(1) << level;
    const glm::u32vec3 c = s.octree_index[i];
    if (c.x >= cells || c.y >= cells || c.z >= cells)
      throw_input_error("{}: voxel {}: octree index ({}, {}, {}) is outside the level-{} grid of {}",
                        name, i, c.x, c.y, c.z, level, cells);
    for (float d : s.corner_density[i])
      if (!std::isfinite(d)) throw_input_error("{}: voxel {}: corner density is not finite", name, i);
    const float* sh = s.voxel_sh(i);
    for (int k = 0; k < s.sh_coeffs() * 3; ++k)
      if (!std::isfinite(sh[k])) throw_input_error("{}: voxel {}: SH coefficient is not finite", name, i);
  }
}

}  // namespace lfd::scene
