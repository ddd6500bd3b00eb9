#pragma once
// Small voxel scenes with known answers for the voxel tests.
#include <cmath>

#include "render/camera.hpp"
#include "render/spherical_harmonics.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::voxel::testing {

// The raw density whose scene::exp_linear_11 activation is `sigma` (sigma > 0).
inline float raw_density_for(float sigma) {
  return sigma > 1.1f ? sigma : 1.1f * (std::log(sigma / 1.1f) + 1.0f);
}

// Adds a voxel of constant raw density and view-independent colour `rgb` (SH degree 0).
inline void add_voxel(scene::VoxelScene& s, glm::u32vec3 index, int level, float raw_density, glm::vec3 rgb) {
  const size_t i = s.size();
  s.resize(i + 1);
  s.octree_index[i] = index;
  s.level[i] = uint8_t(level);
  s.corner_density[i].fill(raw_density);
  float* sh = s.voxel_sh(i);
  for (int c = 0; c < 3; ++c) sh[c] = scene::color_to_sh_dc(rgb[c]);
}

// A scene of root extent 1 centred at the origin, no supersampling, K = 1, black background.
inline scene::VoxelScene empty_scene() {
  scene::VoxelScene s;
  s.supersampling = 1.0f;
  return s;
}

// A square camera of odd size whose centre pixel's ray runs from `eye` through `target`.
inline render::Camera camera_through(glm::vec3 eye, glm::vec3 target, int size = 17) {
  const glm::vec3 d = glm::normalize(target - eye);
  const glm::vec3 up = std::abs(d.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return render::make_look_at_camera(eye, target, up, 0.5f, size, size);
}

}  // namespace lfd::voxel::testing
