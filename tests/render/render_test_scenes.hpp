#pragma once
// Small scenes built in code for the render tests (fixed seeds).
#include <cmath>
#include <random>

#include "scene/gaussian_scene.hpp"
#include "render/spherical_harmonics.hpp"

namespace lfd::render::testing {

// Appends one Gaussian with DC colour `rgb` (degree-0 SH: scene::sh_dc_to_color(sh0) = rgb).
inline void add_gaussian(scene::GaussianScene& s, std::array<float, 3> pos, std::array<float, 3> scale,
                         float opacity, std::array<float, 3> rgb,
                         std::array<float, 4> q = {1.0f, 0.0f, 0.0f, 0.0f}) {
  s.positions.push_back(pos);
  s.scales.push_back(scale);
  s.rotations.push_back(q);
  s.opacities.push_back(opacity);
  const int coeffs = s.sh_coeffs();
  for (int c = 0; c < 3; ++c) s.sh.push_back(scene::color_to_sh_dc(rgb[size_t(c)]));
  for (int k = 1; k < coeffs; ++k)
    for (int c = 0; c < 3; ++c) s.sh.push_back(0.0f);
}

// A cloud of `n` random Gaussians in front of a camera at the origin looking down +z:
// depths in [z_near, z_far], lateral extent that fills a ~40 degree view.
inline scene::GaussianScene random_cloud(int n, float z_near, float z_far, uint32_t seed) {
  scene::GaussianScene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  for (int i = 0; i < n; ++i) {
    const float z = z_near + (z_far - z_near) * u01(rng);
    const float x = (u01(rng) - 0.5f) * 0.8f * z, y = (u01(rng) - 0.5f) * 0.8f * z;
    const float base = 0.004f * z;
    std::array<float, 4> q{u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f, u01(rng) - 0.5f};
    const float len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (auto& v : q) v /= len;
    add_gaussian(s, {x, y, z}, {base * (0.5f + 2.0f * u01(rng)), base * (0.5f + 2.0f * u01(rng)), base * (0.5f + u01(rng))},
                 0.3f + 0.65f * u01(rng), {u01(rng), u01(rng), u01(rng)}, q);
  }
  return s;
}

}  // namespace lfd::render::testing
