#include "scene/scene_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lfd::scene {

std::array<float, 3> SceneBounds::center() const {
  return {0.5f * (min[0] + max[0]), 0.5f * (min[1] + max[1]), 0.5f * (min[2] + max[2])};
}

std::array<float, 3> SceneBounds::extent() const {
  return {max[0] - min[0], max[1] - min[1], max[2] - min[2]};
}

float SceneBounds::radius() const {
  const auto e = extent();
  return 0.5f * std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
}

SceneBounds robust_bounds(const GaussianScene& scene, double lower_quantile,
                          double upper_quantile) {
  SceneBounds b;
  const size_t n = scene.size();
  if (n == 0) return b;
  lower_quantile = std::clamp(lower_quantile, 0.0, 1.0);
  upper_quantile = std::clamp(upper_quantile, lower_quantile, 1.0);
  constexpr size_t kMaxSamples = 1 << 20;
  const size_t stride = (n + kMaxSamples - 1) / kMaxSamples;
  std::vector<float> values;
  values.reserve(n / stride + 1);
  for (int axis = 0; axis < 3; ++axis) {
    values.clear();
    for (size_t i = 0; i < n; i += stride) values.push_back(scene.positions[i][axis]);
    const size_t m = values.size();
    const auto at = [&](double q) {
      const size_t k = std::min(m - 1, size_t(std::floor(q * double(m - 1) + 0.5)));
      std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
      return values[k];
    };
    b.min[axis] = at(lower_quantile);
    b.max[axis] = at(upper_quantile);
  }
  return b;
}

SceneBounds content_bounds(const GaussianScene& scene, double lower_quantile,
                           double upper_quantile, float min_opacity) {
  SceneBounds b;
  constexpr size_t kMaxSamples = 1 << 20;
  const size_t stride = (scene.size() + kMaxSamples - 1) / kMaxSamples;
  std::vector<std::pair<float, float>> values;  // (coordinate, opacity)
  for (int axis = 0; axis < 3; ++axis) {
    values.clear();
    double total = 0;
    for (size_t i = 0; i < scene.size(); i += stride) {
      // A scene of centres only (positions without opacities) counts every centre as opaque.
      const float opacity = i < scene.opacities.size() ? scene.opacities[i] : 1.0f;
      if (opacity >= min_opacity) {
        values.emplace_back(scene.positions[i][axis], opacity);
        total += opacity;
      }
    }
    if (values.empty()) return SceneBounds{};
    std::sort(values.begin(), values.end());
    const auto at = [&](double q) {
      double sum = 0;
      for (const auto& [x, w] : values)
        if ((sum += w) >= q * total) return x;
      return values.back().first;
    };
    b.min[axis] = at(std::clamp(lower_quantile, 0.0, 1.0));
    b.max[axis] = at(std::clamp(upper_quantile, lower_quantile, 1.0));
  }
  return b;
}

SceneBounds exact_bounds(const GaussianScene& scene) {
  SceneBounds b;
  if (scene.size() == 0) return b;
  b.min = b.max = scene.positions[0];
  for (const auto& p : scene.positions)
    for (int a = 0; a < 3; ++a) {
      b.min[a] = std::min(b.min[a], p[a]);
      b.max[a] = std::max(b.max[a], p[a]);
    }
  return b;
}

}  // namespace lfd::scene
