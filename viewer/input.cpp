#include "viewer/input.hpp"

#include <algorithm>

#include <numbers>

namespace lfd::viewer {

bool InputEvents::any() const {
  return drag_dx_px != 0 || drag_dy_px != 0 || pan_dx_px != 0 || pan_dy_px != 0 || wheel_steps != 0 ||
         orbit_keys_x != 0 || orbit_keys_y != 0 || pan_keys_x != 0 || pan_keys_y != 0 ||
         zoom_keys != 0 || reset;
}

void apply_input(const InputEvents& in, int window_height_px, double dt_s, OrbitCamera& camera) {
  if (in.reset) {
    camera.reset();
    return;
  }
  const double h = std::max(window_height_px, 1);
  const float pi = std::numbers::pi_v<float>;
  // Dragging right turns the scene right (the camera orbits left); dragging up tilts it up.
  const float yaw = float(-in.drag_dx_px / h) * pi + float(in.orbit_keys_x * dt_s) * pi / 2;
  const float pitch = float(in.drag_dy_px / h) * pi + float(in.orbit_keys_y * dt_s) * pi / 2;
  if (yaw != 0 || pitch != 0) camera.orbit(yaw, pitch);
  const float pan_x = float(in.pan_dx_px / h) + float(in.pan_keys_x * dt_s) * 0.5f;
  const float pan_y = float(-in.pan_dy_px / h) + float(in.pan_keys_y * dt_s) * 0.5f;
  if (pan_x != 0 || pan_y != 0) camera.pan(pan_x, pan_y);
  const float zoom = float(in.wheel_steps + in.zoom_keys * dt_s * 10.0);
  if (zoom != 0) camera.zoom(zoom);
}

}  // namespace lfd::viewer
