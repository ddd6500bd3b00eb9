#pragma once
// Live calibration (`lfd calibrate --live`, DESIGN section 5): rounds of show patterns ->
// photograph them -> calibrate, each round making its patterns for the previous round's
// result, so the phase the camera decodes shrinks toward f_seen alone and the last round's
// estimate is made with nearly matched patterns.
//
// One loop, two sets of devices (calib/live_devices.hpp):
//   hardware   a full-screen GLFW window on the display's monitor and a cv::VideoCapture
//              camera (calib/live/hardware_live_calibration.hpp; one physical camera, so the
//              user is asked to move it between positions);
//   simulated  (--simulate TRUTH.json) the pattern is remembered and photographed by the
//              optics simulator looking at a TRUE unit from known poses: the loop's test.
// Per round and camera position: the white pattern is shown while the camera fixes its
// exposure, then every pattern of the manifest is shown and photographed in turn; the
// photographs go to calibrate_display exactly as `lfd calibrate DIR` would read them.
#include <functional>
#include <string>

#include "calib/calibrate.hpp"
#include "calib/live_devices.hpp"

namespace lfd::calib {

struct LiveOptions {
  CalibrateOptions calibrate;
  int rounds = 2;
  int positions = 1;          // camera positions per round
  int capture_width_px = 640; // simulated: camera width
  // Hardware: the monitor whose GLFW name starts with this (Looking Glass EDID names start
  // with "LKG"); if none or several do, the one at the display's resolution.
  std::string monitor_prefix = "LKG";
  int camera_index = 0;       // hardware: cv::VideoCapture index (/dev/videoN)
  int frames_averaged = 4;    // hardware: frames averaged per photograph (noise / sqrt(n))
  int settle_ms = 200;        // hardware: wait after a pattern is on screen (panel response)
  // Hardware: let exposure, white balance and focus settle on the white pattern at each
  // position, then lock them; false leaves them as the user set them (v4l2-ctl).
  bool lock_camera_settings = true;
  // Called, with the board on screen to aim at, before the photographs of each position the
  // camera must be brought to (every position when positions > 1, else round 1's only), with
  // the position (1-based) and the count: the hardware mode asks the user to move the camera.
  std::function<void(int, int)> move_camera;
  // Called after each round with its number and outcome (progress, tests).
  std::function<void(int, const CalibrationOutcome&)> on_round;
};

// The loop: `options.rounds` rounds of `options.positions` positions each, starting from the
// nominal description. Throws InputError for captures calibrate_display refuses.
CalibrationOutcome run_live_calibration(const Calibration& nominal, PatternDisplay& display,
                                        FrameSource& camera, const LiveOptions& options);

// The loop against the simulator: the camera (realistic effects, make_capture_rig) looks at
// `truth` from `options.positions` poses; its intrinsics are given to the solver.
CalibrationOutcome run_live_calibration_simulated(const Calibration& nominal,
                                                  const Calibration& truth,
                                                  const LiveOptions& options);

}  // namespace lfd::calib
