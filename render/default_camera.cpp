#include "render/default_camera.hpp"

#include <algorithm>
#include <cmath>

#include "render/scene_bounds.hpp"

namespace lfd::render {

CameraSpec frame_scene(const GaussianScene& scene, float fov_y_deg, float orbit_deg) {
  const SceneBounds b = robust_bounds(scene);
  const auto c = b.center();
  const glm::vec3 center(c[0], c[1], c[2]);
  // The box's half-diagonal overstates a flat scene's depth; the sphere of the larger
  // cross-section (x, y) plus half the depth keeps the subject in view from the front.
  const auto e = b.extent();
  const float radius = std::max({0.5f * std::sqrt(e[0] * e[0] + e[1] * e[1]), 0.5f * e[2], 1e-3f});
  const float half_fov = 0.5f * fov_y_deg * float(M_PI) / 180.0f;
  const float distance = radius / std::sin(half_fov) + 0.5f * e[2];
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
