// The live loop with the real pattern window in it (Xvfb): every pattern goes through GL onto
// the virtual screen, and the simulated camera photographs the window's framebuffer, so the
// calibration recovers the truth only if the window showed each pattern exactly.
#include <gtest/gtest.h>

#include "gpu/gl/glfw_session.hpp"
#include "live/pattern_window.hpp"
#include "live/live_calibration.hpp"
#include "live/simulated_live_devices.hpp"
#include "display/visual_json.hpp"
#include "tests/live/window/live_test_display.hpp"

namespace lfd::live {
namespace {

TEST(LiveCalibrationOnScreen, RecoversTheTruthFromPhotographsOfTheWindow) {
  const sim::SyntheticUnit unit = sim::make_synthetic_unit(display::read_visual_json(test::live_test_display()));
  const display::DisplayCalibration& d = unit.truth.display;
  const gpu::GlfwSession glfw;
  PatternWindow window(glfw, glfw.find_display_monitor("LKG", d.screen_w, d.screen_h),
                       d.screen_w, d.screen_h);
  // The sizes and bounds of the simulated live test (calibrate_live_test.cpp), in one round:
  // refining over rounds is that test's subject, the window in the loop this one's.
  sim::CaptureRig rig = sim::make_capture_rig(d, 480, 2, false);
  LiveOptions o;
  o.rounds = 1;
  o.positions = 2;
  o.calibrate.camera = rig.intrinsics;
  int photographs = 0;
  SimulatedCamera camera(unit.truth, rig, [&] {
    ++photographs;
    return window.read_back();
  });
  std::vector<sim::CalibrationErrors> errors;
  o.on_round = [&](int, const calib::CalibrationOutcome& out) {
    errors.push_back(sim::compare_with_truth(out.calibration, unit.truth));
  };
  const sim::CalibrationErrors before = sim::compare_with_truth(unit.nominal, unit.truth);
  const calib::CalibrationOutcome out = run_live_calibration(unit.nominal, window, camera, o);
  EXPECT_GT(photographs, 0);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_LT(errors[0].phase_rms_periods, 0.2 * before.phase_rms_periods);
  EXPECT_LT(errors[0].pitch_rel, 3e-4);
  EXPECT_LT(errors[0].slant_deg, 0.005);
  EXPECT_TRUE(out.gate_failures.empty());
}

}  // namespace
}  // namespace lfd::live
