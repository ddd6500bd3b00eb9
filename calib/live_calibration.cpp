#include "calib/live_calibration.hpp"

#include "calib/synthetic_unit.hpp"
#include "util/error.hpp"

namespace lfd::calib {

CalibrationOutcome run_live_calibration_simulated(const Calibration& nominal,
                                                  const Calibration& truth,
                                                  const LiveOptions& options) {
  if (truth.display.screen_w != nominal.display.screen_w ||
      truth.display.screen_h != nominal.display.screen_h)
    throw_input_error("--simulate: the true display is {}x{}, the nominal one {}x{}",
                      truth.display.screen_w, truth.display.screen_h, nominal.display.screen_w,
                      nominal.display.screen_h);
  const CaptureRig rig =
      make_capture_rig(truth.display, options.capture_width_px, options.positions, false);
  CalibrateOptions co = options.calibrate;
  co.camera = rig.intrinsics;  // the simulated camera's intrinsics are known exactly
  Calibration current = nominal;
  CalibrationOutcome outcome;
  for (int round = 1; round <= std::max(1, options.rounds); ++round) {
    const PatternSet set = plan_patterns(current);
    // "Showing" a pattern = the simulator photographing the true unit displaying it.
    const auto captures = simulate_captures(set, truth, rig);
    outcome = calibrate_display(set, captures, co);
    if (options.on_round) options.on_round(round, outcome);
    current = outcome.calibration;
    // The next round's patterns use the estimate, but its view cone stays the nominal one
    // (visual.json's viewCone; the measured one is kept separately).
  }
  return outcome;
}

CalibrationOutcome run_live_calibration_on_hardware(const Calibration&, const LiveOptions&) {
  throw_input_error(
      "--live without --simulate (GLFW window + camera) is not available in this build yet; use "
      "the offline workflow (lfd patterns, photograph, lfd calibrate DIR) or --simulate");
}

}  // namespace lfd::calib
