#include "render/default_camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/scene_bounds.hpp"

namespace lfd::render {
namespace {

// The q-quantile of the centres' distances from `center` (deterministic subsample).
float distance_quantile(const scene::GaussianScene& scene, const glm::vec3& center, double q) {
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

// The least distance from `center` along -`forward` at which the Gaussians holding
// kFramedOpacity of the content's opacity project inside the view's tangents `tan_x`, `tan_y`:
// each Gaussian needs D >= |x| / tan_x - depth (and likewise for y), where depth is measured
// from the centre along the view; the distance is the opacity-weighted quantile of those needs.
float fitting_distance(const scene::GaussianScene& scene, const glm::vec3& center,
                       const glm::vec3& forward, const glm::vec3& right, const glm::vec3& up,
                       float tan_x, float tan_y) {
  const size_t step = std::max<size_t>(1, scene.size() / 200000);
  std::vector<std::pair<float, float>> needs;  // (distance, opacity)
  double total = 0;
  for (size_t i = 0; i < scene.size(); i += step) {
    const float opacity = i < scene.opacities.size() ? scene.opacities[i] : 1.0f;  // as scene::content_bounds
    if (opacity < kContentMinOpacity) continue;
    const auto& p = scene.positions[i];
    const glm::vec3 d = glm::vec3(p[0], p[1], p[2]) - center;
    const float depth = glm::dot(d, forward);
    const float need = std::max({std::fabs(glm::dot(d, right)) / tan_x - depth,
                                 std::fabs(glm::dot(d, up)) / tan_y - depth, 0.2f - depth});
    needs.emplace_back(need, opacity);
    total += opacity;
  }
  if (needs.empty()) return 1.0f;
  std::sort(needs.begin(), needs.end());
  double sum = 0;
  for (const auto& [need, w] : needs)
    if ((sum += w) >= kFramedOpacity * total) return need;
  return needs.back().first;
}

}  // namespace

CameraSpec frame_scene(const scene::GaussianScene& scene, float fov_y_deg, float orbit_deg, float aspect) {
  scene::SceneBounds box = scene::content_bounds(scene, 0.05, 0.95, kContentMinOpacity);
  if (box.radius() <= 0.0f) box = scene::robust_bounds(scene);  // no Gaussian carries opacity
  const auto c = box.center();
  const glm::vec3 center(c[0], c[1], c[2]);
  const glm::vec3 up(0.0f, -1.0f, 0.0f);  // COLMAP / 3DGS: y points down
  const float orbit = orbit_deg * float(M_PI) / 180.0f;
  const float elevation = kDefaultElevationDeg * float(M_PI) / 180.0f;
  // Forward: +z turned about the up axis by the orbit, then tilted down (towards +y).
  const glm::vec3 level(std::sin(orbit), 0.0f, std::cos(orbit));
  const glm::vec3 forward = std::cos(elevation) * level + std::sin(elevation) * -up;
  const glm::vec3 right = glm::normalize(glm::cross(forward, up));
  const glm::vec3 camera_up = glm::cross(right, forward);
  const float tan_y = std::tan(0.5f * fov_y_deg * float(M_PI) / 180.0f) * (1.0f - kFrameMargin);
  const float tan_x = tan_y * std::max(aspect, 1e-3f);
  float distance =
      std::max(fitting_distance(scene, center, forward, right, camera_up, tan_x, tan_y), 1e-3f);
  // An enclosing shell (a sky dome, the walls of a room): stay inside it, at 85% of its
  // distance, rather than render its outside.
  const float r90 = std::max(distance_quantile(scene, center, 0.9), 1e-3f);
  const float r99 = std::max(distance_quantile(scene, center, 0.99), r90);
  if (r99 > 2.0f * r90) distance = std::min(distance, 0.85f * r99);
  CameraSpec s;
  s.position = center - distance * forward;
  s.look_at = center;
  s.up = up;
  s.fov_y_deg = fov_y_deg;
  return s;
}

}  // namespace lfd::render
