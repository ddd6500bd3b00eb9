#pragma once
// Mouse and keys to camera moves, for both windows: left drag orbits, right drag (or shift +
// left drag) pans, the wheel zooms, arrows orbit, WASD pan, +/- zoom, R resets. Pure: GLFW
// callbacks fill an InputEvents, apply_input turns it into OrbitCamera calls (table-tested).
#include "viewer/orbit_camera.hpp"

namespace lfd::viewer {

struct InputEvents {
  double drag_dx_px = 0, drag_dy_px = 0;  // left-button drag since the last frame (y down)
  double pan_dx_px = 0, pan_dy_px = 0;    // right-button (or shift) drag
  double wheel_steps = 0;
  int orbit_keys_x = 0, orbit_keys_y = 0;  // arrows held: -1, 0, +1
  int pan_keys_x = 0, pan_keys_y = 0;      // A/D, S/W held
  int zoom_keys = 0;                       // +/- held
  bool reset = false;
  bool any() const;
};

// Applies one frame's input: a drag across the whole window height turns 180 degrees; keys move
// at a fixed rate per second (frame time `dt_s`).
void apply_input(const InputEvents& in, int window_height_px, double dt_s, OrbitCamera& camera);

}  // namespace lfd::viewer
