#pragma once
// A pinhole camera in the conventions of the 3DGS reference rasterizer
// (docs/rendering.md "Cameras and quilt geometry"): camera space +x right, +y down, +z forward,
// pixel centres at integer coordinates, centred frustum plus an optional principal-point
// shift (an off-axis frustum: the quilt's view cameras, docs/rendering.md).
#include <array>

#include <glm/glm.hpp>

namespace lfd::render {

struct Camera {
  glm::vec3 position_world{0.0f};
  // Rows: the camera's right, down and forward axes in world coordinates.
  glm::mat3 world_to_camera{1.0f};
  float fov_x_rad = 1.0f;
  float fov_y_rad = 1.0f;
  int width = 0;
  int height = 0;
  // Principal-point shift in NDC units (paper: p_j), added to the projected NDC coordinate:
  // ndc_x = x / (z tan(fov_x/2)) + shift_x. 0 = centred.
  float shift_x_ndc = 0.0f;
  float shift_y_ndc = 0.0f;
  float znear = 0.01f;  // only enters the unused NDC z (reference defaults)
  float zfar = 100.0f;

  float tan_half_fov_x() const;
  float tan_half_fov_y() const;
  float focal_x_px() const;  // W / (2 tan(fov_x/2))
  float focal_y_px() const;
  glm::vec3 right() const { return glm::vec3(world_to_camera[0][0], world_to_camera[1][0], world_to_camera[2][0]); }
  glm::vec3 down() const { return glm::vec3(world_to_camera[0][1], world_to_camera[1][1], world_to_camera[2][1]); }
  glm::vec3 forward() const { return glm::vec3(world_to_camera[0][2], world_to_camera[1][2], world_to_camera[2][2]); }

  glm::vec3 to_camera(const glm::vec3& p_world) const {
    return world_to_camera * (p_world - position_world);
  }
  // The reference's full_proj_transform applied to a world point, divided by w + 1e-7
  // (preprocessCUDA): NDC x, y in [-1, 1] across the image; +y is down.
  glm::vec2 project_ndc(const glm::vec3& p_world) const;
  // ndc2Pix: ((ndc + 1) * S - 1) / 2, so pixel (i, j) is centred at (i, j).
  glm::vec2 project_px(const glm::vec3& p_world) const;
  // The reference's 4x4 matrices (getProjectionMatrix; column-major, GLM), with the
  // principal-point shift in P[0][2], P[1][2]; for GL ports. view * world point = camera point.
  glm::mat4 view_matrix() const;
  glm::mat4 projection_matrix() const;
};

// Camera at `position` looking at `look_at`, `up` roughly up in the image. fov_y in radians;
// fov_x follows from the aspect so pixels are square: tan(fov_x/2) = tan(fov_y/2) * W / H.
// Throws InputError for degenerate input (coincident points, up parallel to the view, bad size).
Camera make_look_at_camera(const glm::vec3& position, const glm::vec3& look_at,
                           const glm::vec3& up, float fov_y_rad, int width, int height);

}  // namespace lfd::render
