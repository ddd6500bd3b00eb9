#include "scene/scene_checks.hpp"

#include <cmath>

#include "util/error.hpp"

namespace lfd::scene {

float sigmoid(float logit) { return 1.0f / (1.0f + std::exp(-logit)); }

void resize_scene(GaussianScene& scene, size_t count, int sh_degree) {
  scene.sh_degree = sh_degree;
  scene.positions.assign(count, {0, 0, 0});
  scene.scales.assign(count, {0, 0, 0});
  scene.rotations.assign(count, {1, 0, 0, 0});
  scene.opacities.assign(count, 0.0f);
  scene.sh.assign(count * size_t(scene.sh_coeffs()) * 3, 0.0f);
}

namespace {

bool all_finite(const float* v, size_t n) {
  for (size_t k = 0; k < n; ++k)
    if (!std::isfinite(v[k])) return false;
  return true;
}

}  // namespace

void finalize_scene(GaussianScene& scene, const std::string& name) {
  const size_t n = scene.size();
  if (scene.sh_degree < 0 || scene.sh_degree > 3)
    throw_input_error("{}: SH degree {} is not in 0..3", name, scene.sh_degree);
  if (scene.scales.size() != n || scene.rotations.size() != n || scene.opacities.size() != n ||
      scene.sh.size() != n * size_t(scene.sh_coeffs()) * 3)
    throw_input_error("{}: inconsistent attribute array sizes", name);
  const size_t coeffs = size_t(scene.sh_coeffs()) * 3;
  for (size_t i = 0; i < n; ++i) {
    if (!all_finite(scene.positions[i].data(), 3))
      throw_input_error("{}: Gaussian {}: position is not finite", name, i);
    if (!all_finite(scene.scales[i].data(), 3))
      throw_input_error("{}: Gaussian {}: scale is not finite", name, i);
    for (float s : scene.scales[i])
      if (s < 0.0f) throw_input_error("{}: Gaussian {}: scale {} is negative", name, i, s);
    if (!std::isfinite(scene.opacities[i]))
      throw_input_error("{}: Gaussian {}: opacity is not finite", name, i);
    if (!all_finite(scene.sh.data() + i * coeffs, coeffs))
      throw_input_error("{}: Gaussian {}: colour (SH) is not finite", name, i);
    auto& q = scene.rotations[i];
    if (!all_finite(q.data(), 4))
      throw_input_error("{}: Gaussian {}: rotation is not finite", name, i);
    const double norm = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] +
                                  double(q[2]) * q[2] + double(q[3]) * q[3]);
    if (!(norm > 1e-12) || !std::isfinite(norm))
      throw_input_error("{}: Gaussian {}: rotation quaternion has zero length", name, i);
    for (float& c : q) c = float(c / norm);
  }
}

}  // namespace lfd::scene
