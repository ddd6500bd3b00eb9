#include "render/camera.hpp"

#include <cmath>

#include "util/error.hpp"

namespace lfd::render {

float Camera::tan_half_fov_x() const { return std::tan(0.5f * fov_x_rad); }
float Camera::tan_half_fov_y() const { return std::tan(0.5f * fov_y_rad); }
float Camera::focal_x_px() const { return float(width) / (2.0f * tan_half_fov_x()); }
float Camera::focal_y_px() const { return float(height) / (2.0f * tan_half_fov_y()); }

glm::vec2 Camera::project_ndc(const glm::vec3& p_world) const {
  const glm::vec3 t = to_camera(p_world);
  // P[0][0] = 1/tan, P[0][2] = shift, P[3][2] = 1 (w = z); then / (w + 1e-7) as forward.cu.
  const float inv_w = 1.0f / (t.z + 1e-7f);
  return {(t.x / tan_half_fov_x() + shift_x_ndc * t.z) * inv_w,
          (t.y / tan_half_fov_y() + shift_y_ndc * t.z) * inv_w};
}

glm::vec2 Camera::project_px(const glm::vec3& p_world) const {
  const glm::vec2 ndc = project_ndc(p_world);
  return {((ndc.x + 1.0f) * float(width) - 1.0f) * 0.5f, ((ndc.y + 1.0f) * float(height) - 1.0f) * 0.5f};
}

glm::mat4 Camera::view_matrix() const {
  glm::mat4 v(world_to_camera);
  const glm::vec3 t = -(world_to_camera * position_world);
  v[3] = glm::vec4(t, 1.0f);
  return v;
}

glm::mat4 Camera::projection_matrix() const {
  glm::mat4 p(0.0f);  // p[col][row]
  p[0][0] = 1.0f / tan_half_fov_x();
  p[1][1] = 1.0f / tan_half_fov_y();
  p[2][0] = shift_x_ndc;
  p[2][1] = shift_y_ndc;
  p[2][3] = 1.0f;
  p[2][2] = zfar / (zfar - znear);
  p[3][2] = -(zfar * znear) / (zfar - znear);
  return p;
}

Camera make_look_at_camera(const glm::vec3& position, const glm::vec3& look_at,
                           const glm::vec3& up, float fov_y_rad, int width, int height) {
  if (width <= 0 || height <= 0) throw_input_error("camera: image size {}x{} is not positive", width, height);
  if (!(fov_y_rad > 0.0f && fov_y_rad < 3.1f)) throw_input_error("camera: fov_y must lie in (0, 178) degrees");
  const glm::vec3 fwd_raw = look_at - position;
  if (!(glm::length(fwd_raw) > 0.0f)) throw_input_error("camera: position and look_at coincide");
  const glm::vec3 forward = glm::normalize(fwd_raw);
  const glm::vec3 right_raw = glm::cross(forward, up);  // x right = forward x up (y down)
  if (!(glm::length(right_raw) > 1e-6f * glm::length(up)) || !(glm::length(up) > 0.0f))
    throw_input_error("camera: up is zero or parallel to the viewing direction");
  const glm::vec3 right = glm::normalize(right_raw);
  const glm::vec3 down = glm::cross(forward, right);
  Camera c;
  c.position_world = position;
  // GLM is column-major: m[col][row]; rows are right, down, forward.
  for (int i = 0; i < 3; ++i) {
    c.world_to_camera[i][0] = right[i];
    c.world_to_camera[i][1] = down[i];
    c.world_to_camera[i][2] = forward[i];
  }
  c.width = width;
  c.height = height;
  c.fov_y_rad = fov_y_rad;
  c.fov_x_rad = 2.0f * std::atan(std::tan(0.5f * fov_y_rad) * float(width) / float(height));
  return c;
}

}  // namespace lfd::render
