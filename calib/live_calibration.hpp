#pragma once
// Live calibration (`lfd calibrate --live`, DESIGN section 5): rounds of show patterns ->
// grab frames -> calibrate, each round making its patterns for the previous round's result,
// so the phase the camera decodes shrinks toward f_seen alone and the last round's
// estimate is made with nearly matched patterns. With --simulate the frames come from the
// optics simulator looking at a TRUE unit (no window, no camera): that is how the loop is
// tested.
#include <functional>
#include <string>

#include "calib/calibrate.hpp"

namespace lfd::calib {

struct LiveOptions {
  CalibrateOptions calibrate;
  int rounds = 2;
  int positions = 1;          // simulated: camera positions per round
  int capture_width_px = 640; // simulated: camera width
  std::string monitor_prefix = "LKG";
  int camera_index = 0;
  // Called after each round with its number and outcome (progress, tests).
  std::function<void(int, const CalibrationOutcome&)> on_round;
};

CalibrationOutcome run_live_calibration_simulated(const Calibration& nominal,
                                                  const Calibration& truth,
                                                  const LiveOptions& options);

// Full-screen patterns on the display's monitor (GLFW) and frames from cv::VideoCapture.
// Not available in this build: throws InputError saying so.
CalibrationOutcome run_live_calibration_on_hardware(const Calibration& nominal,
                                                    const LiveOptions& options);

}  // namespace lfd::calib
