#include "viewer/orbit_camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace lfd::viewer {
namespace {

glm::vec3 rotate(const glm::vec3& v, const glm::vec3& axis, float angle) {
  return glm::vec3(glm::rotate(glm::mat4(1.0f), angle, glm::normalize(axis)) * glm::vec4(v, 0.0f));
}

}  // namespace

OrbitCamera::OrbitCamera(const render::CameraSpec& start) : start_(start), spec_(start) {}

float OrbitCamera::distance() const { return glm::length(spec_.position - spec_.look_at); }

void OrbitCamera::orbit(float yaw_rad, float pitch_rad) {
  const glm::vec3 up = glm::normalize(spec_.up);
  glm::vec3 offset = spec_.position - spec_.look_at;
  offset = rotate(offset, up, yaw_rad);
  // Pitch about the camera's right axis, limited to stay 5 degrees from either pole.
  const float r = glm::length(offset);
  const float elevation = std::asin(std::clamp(glm::dot(offset / r, up), -1.0f, 1.0f));
  const float limit = glm::radians(85.0f);
  const float new_elevation = std::clamp(elevation + pitch_rad, -limit, limit);
  const glm::vec3 right = glm::normalize(glm::cross(up, offset));
  offset = rotate(offset, right, -(new_elevation - elevation));
  spec_.position = spec_.look_at + offset;
}

void OrbitCamera::pan(float dx, float dy) {
  const glm::vec3 forward = glm::normalize(spec_.look_at - spec_.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::normalize(spec_.up)));
  const glm::vec3 up = glm::cross(right, forward);
  const float view_height = 2.0f * distance() * std::tan(glm::radians(spec_.fov_y_deg) / 2.0f);
  // Dragging right moves the scene right: the camera goes left.
  const glm::vec3 move = (-dx * right - dy * up) * view_height;
  spec_.position += move;
  spec_.look_at += move;
}

void OrbitCamera::zoom(float steps) {
  const glm::vec3 offset = spec_.position - spec_.look_at;
  const float scale = std::exp(-0.1f * steps);
  spec_.position = spec_.look_at + offset * std::max(scale, 1e-3f / std::max(glm::length(offset), 1e-6f));
}

}  // namespace lfd::viewer
