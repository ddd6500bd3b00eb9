// The live loop with the real pattern window in it (Xvfb): every pattern goes through GL onto
// the virtual screen, and the simulated camera photographs the window's framebuffer, so the
// calibration recovers the truth only if the window showed each pattern exactly.
#include <gtest/gtest.h>

#include "gpu/glfw_session.hpp"
#include "calib/live/pattern_window.hpp"
#include "calib/live_calibration.hpp"
#include "calib/simulated_live_devices.hpp"
#include "calib/display/visual_json.hpp"
#include "tests/calib/live/live_test_display.hpp"

namespace lfd::calib {
namespace {

TEST(LiveCalibrationOnScreen, RecoversTheTruthFromPhotographsOfTheWindow) {
  const SyntheticUnit unit = make_synthetic_unit(read_visual_json(test::live_test_display()));
  const DisplayCalibration& d = unit.truth.display;
  const gpu::GlfwSession glfw;
  PatternWindow window(glfw, glfw.find_display_monitor("LKG", d.screen_w, d.screen_h),
                       d.screen_w, d.screen_h);
  // The sizes and bounds of the simulated live test (calibrate_live_test.cpp), in one round:
  // refining over rounds is that test's subject, the window in the loop this one's.
  CaptureRig rig = make_capture_rig(d, 480, 2, false);
  LiveOptions o;
  o.rounds = 1;
  o.positions = 2;
  o.calibrate.camera = rig.intrinsics;
  int photographs = 0;
  SimulatedCamera camera(unit.truth, rig, [&] {
    ++photographs;
    return window.read_back();
  });
  std::vector<CalibrationErrors> errors;
  o.on_round = [&](int, const CalibrationOutcome& out) {
    errors.push_back(compare_with_truth(out.calibration, unit.truth));
  };
  const CalibrationErrors before = compare_with_truth(unit.nominal, unit.truth);
  const CalibrationOutcome out = run_live_calibration(unit.nominal, window, camera, o);
  EXPECT_GT(photographs, 0);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_LT(errors[0].phase_rms_periods, 0.2 * before.phase_rms_periods);
  EXPECT_LT(errors[0].pitch_rel, 3e-4);
  EXPECT_LT(errors[0].slant_deg, 0.005);
  EXPECT_TRUE(out.gate_failures.empty());
}

}  // namespace
}  // namespace lfd::calib
