#include "render/default_camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/scene_bounds.hpp"

namespace lfd::render {
namespace {

// The q-quantile of the centres' distances from `center` (deterministic subsample).
float distance_quantile(const GaussianScene& scene, const glm::vec3& center, double q) {
  const size_t step = std::max<size_t>(1, scene.size() / 200000);
  std::vector<float> d;
  d.reserve(scene.size() / step + 1);
  for (size_t i = 0; i < scene.size(); i += step) {
    const auto& p = scene.positions[i];
    d.push_back(glm::length(glm::vec3(p[0], p[1], p[2]) - center));
  }
  if (d.empty()) return 1.0f;
  const auto nth = d.begin() + ptrdiff_t(q * double(d.size() - 1));
  std::nth_element(d.begin(), nth, d.end());
  return *nth;
}

}  // namespace

CameraSpec frame_scene(const GaussianScene& scene, float fov_y_deg, float orbit_deg) {
  // Centre: the middle of the 25-75% box, which ignores floaters and enclosing backgrounds.
  const SceneBounds core = robust_bounds(scene, 0.25, 0.75);
  const auto c = core.center();
  const glm::vec3 center(c[0], c[1], c[2]);
  // Radius: 90% of the centres lie within it; a bounding box (even a 1-99% one) would be decided
  // by a background dome or far walls. When such an enclosing shell exists (the 99% distance
  // far beyond the 90% one) the camera stays inside it, at 85% of its distance.
  const float r90 = std::max(distance_quantile(scene, center, 0.9), 1e-3f);
  const float r99 = std::max(distance_quantile(scene, center, 0.99), r90);
  const float half_fov = 0.5f * fov_y_deg * float(M_PI) / 180.0f;
  float distance = r90 / std::sin(half_fov);
  if (r99 > 2.0f * r90) distance = std::min(distance, 0.85f * r99);
  const float orbit = orbit_deg * float(M_PI) / 180.0f;
  const glm::vec3 backward(-std::sin(orbit), 0.0f, -std::cos(orbit));
  CameraSpec s;
  s.position = center + distance * backward;
  s.look_at = center;
  s.up = glm::vec3(0.0f, -1.0f, 0.0f);
  s.fov_y_deg = fov_y_deg;
  return s;
}

}  // namespace lfd::render
