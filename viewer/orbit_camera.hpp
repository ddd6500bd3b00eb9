#pragma once
// The viewer's camera: orbit about a target, pan, zoom (mouse and keys). Pure math on a
// render::CameraSpec, so the controls are table-tested without a window and the spec the viewer
// renders is the same cam.json `lfd render --camera` reads.
#include "render/camera_json.hpp"

namespace lfd::viewer {

class OrbitCamera {
 public:
  explicit OrbitCamera(const render::CameraSpec& start);

  // Turns the camera about the target: `yaw_rad` about the up axis, `pitch_rad` about the
  // camera's right axis (stopped 5 degrees short of the up axis so the view never flips).
  void orbit(float yaw_rad, float pitch_rad);
  // Moves camera and target across the view by a fraction of the view height at the target
  // (dx right, dy up), so a drag moves the scene with the mouse at any distance.
  void pan(float dx_view_heights, float dy_view_heights);
  // Multiplies the distance to the target by exp(-0.1 steps) (one mouse wheel notch = 1 step).
  void zoom(float steps);
  void reset() { spec_ = start_; }

  const render::CameraSpec& spec() const { return spec_; }
  float distance() const;

 private:
  render::CameraSpec start_;
  render::CameraSpec spec_;
};

}  // namespace lfd::viewer
