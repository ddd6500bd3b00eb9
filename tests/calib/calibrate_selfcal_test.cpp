// Self-calibration (docs/calibration.md section 3.1): without camera intrinsics (`lfd calibrate`
// without --camera) the boards of three positions calibrate the camera, and the display is
// calibrated through it. Simulated captures as in the round trip, kept small.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "calib/calibrate.hpp"
#include "calib/calibration_stages.hpp"
#include "display/visual_json.hpp"
#include "sim/synthetic_unit.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

struct Simulated {
  sim::SyntheticUnit unit;
  sim::PatternSet set;
  sim::CaptureRig rig;
  std::vector<sim::PositionCaptures> captures;
};

// The round trip's three positions, `side` times further to the side: a planar board fixes
// the focal length only through its perspective, which views within a few degrees of head-on
// hardly show; the fringe points then must (HeadOnPositionsAreCalibratedWithHonestSigmas below).
Simulated simulate(int width_px, double side, int positions = 3) {
  Simulated s;
  s.unit = sim::make_synthetic_unit(display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json")));
  s.set = sim::plan_patterns(s.unit.nominal);
  s.rig = sim::make_capture_rig(s.unit.truth.display, width_px, positions, false);
  for (sim::CameraPose& pose : s.rig.poses) {
    pose.position_m.x() *= side;
    pose.position_m.y() *= side;
  }
  s.captures = sim::simulate_captures(s.set, s.unit.truth, s.rig);
  return s;
}


void expect_camera_near(const sim::CameraIntrinsics& estimate, const sim::CameraIntrinsics& truth, double rel) {
  const cv::Matx33d& t = truth.camera_matrix;
  const cv::Matx33d& k = estimate.camera_matrix;
  std::printf("fx %.1f (true %.1f), fy %.1f (%.1f), cx %.1f (%.1f), cy %.1f (%.1f)\n", k(0, 0),
              t(0, 0), k(1, 1), t(1, 1), k(0, 2), t(0, 2), k(1, 2), t(1, 2));
  EXPECT_NEAR(k(0, 0) / t(0, 0), 1.0, rel);
  EXPECT_NEAR(k(1, 1) / t(1, 1), 1.0, rel);
  EXPECT_NEAR(k(0, 2), t(0, 2), 0.03 * truth.width);
  EXPECT_NEAR(k(1, 2), t(1, 2), 0.03 * truth.height);
}

// 640 px, not 480: since vertical parallax entered the simulator (49042d8) the seam where the
// seen view wraps runs along the slanted lens lines, across the board's squares, and at 480 px
// the farthest position's board is found with 6-7 ChArUco corners only (8 are needed); at 640
// px it shows 14. The bars are the ones this test had before.
//
// The boards alone put the camera 3 % off (fx 632 for 615, principal point 14 px off, the
// cameras 4-5 mm to the side, center 0.026 period): their raw corners carry the lens content
// shift. The fringe points with the shift removed (refine_self_calibration) give fx within
// 1 % and the display within the known-camera bars; the lens solver then frees the focal
// length under that prior and the focal length's error stays within 3 of its reported sigmas.
TEST(CalibrateSelfCalibration, ThreePositionsWithoutIntrinsicsRecoverCameraAndLens) {
  const Simulated s = simulate(640, 3.0);  // three positions about 20 degrees apart
  const CalibrateOptions options;  // no camera: self-calibrated from the boards
  ASSERT_FALSE(options.camera);
  const CalibrationOutcome out = calibrate_display(s.set, s.captures, options);
  ASSERT_TRUE(out.camera_self_calibrated);
  expect_camera_near(out.camera, s.rig.intrinsics, 0.03);
  const double focal_error =
      out.camera.camera_matrix(0, 0) / s.rig.intrinsics.camera_matrix(0, 0) - 1;
  std::printf("focal error %+.4f, sigma %.4f\n", focal_error, out.camera_focal_sigma_rel);
  EXPECT_GT(out.camera_focal_sigma_rel, 0.0);
  EXPECT_LT(std::abs(focal_error), 3 * out.camera_focal_sigma_rel);

  // The display, through the self-calibrated camera.
  const sim::CalibrationErrors e = sim::compare_with_truth(out.calibration, s.unit.truth);
  std::printf("slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg, warp %.4f\n", e.slant_deg,
              e.pitch_rel, e.center_periods, e.view_cone_deg, e.correction_rms_periods);
  for (const auto& f : out.gate_failures) std::printf("gate: %s\n", f.c_str());
  EXPECT_TRUE(out.gate_failures.empty());  // the camera-shift gate fired on the boards' camera
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

// From the round trip's positions, a few degrees from head-on, the boards alone cannot fix the
// focal length (before the fringe refinement: fx 802 for a true 615 at 640 px, with a focal
// sigma under its bound, since the solver took the camera as known and the boards' raw
// corners carry the lens content shift). With the fringe points (lens shift removed) the
// focal length is determined (measured: fx +0.97 %, sigma 0.47 %; view cone 0.22 degree off,
// sigma 0.20): such positions are calibrated, and what is reported must be honest: the focal
// length and the view cone within 3 of their reported sigmas. (One draw against a 2-sigma
// bound fails one time in twenty: this draw went from 1.7 to 2.06 sigmas when the exposure fit
// gained its row-dependent gain and the solver took the field at the content point.)
TEST(CalibrateSelfCalibration, HeadOnPositionsAreCalibratedWithHonestSigmas) {
  const Simulated s = simulate(640, 1.0);
  const CalibrationOutcome out = calibrate_display(s.set, s.captures, CalibrateOptions{});
  const double focal_error =
      out.camera.camera_matrix(0, 0) / s.rig.intrinsics.camera_matrix(0, 0) - 1;
  const sim::CalibrationErrors e = sim::compare_with_truth(out.calibration, s.unit.truth);
  const double cone_sigma = out.calibration.uncertainty.at("view_cone_deg");
  std::printf("focal error %+.4f, sigma %.4f; cone error %.3f, sigma %.3f deg; center %.4f\n",
              focal_error, out.camera_focal_sigma_rel, e.view_cone_deg, cone_sigma,
              e.center_periods);
  EXPECT_LT(out.camera_focal_sigma_rel, CalibrateOptions{}.max_focal_sigma_rel);
  EXPECT_LT(std::abs(focal_error), 3 * out.camera_focal_sigma_rel);
  EXPECT_LT(e.view_cone_deg, 3 * cone_sigma);
  EXPECT_LT(e.center_periods, 0.02);
}

// Positions straight in front of the screen (all on its axis, at three distances) leave the
// focal length undetermined even with the fringes (it trades off against the distance): refused,
// naming what to do.
TEST(CalibrateSelfCalibration, PositionsOnTheScreenAxisAreRefused) {
  const Simulated s = simulate(640, 0.0);
  try {
    const CalibrationOutcome out = calibrate_display(s.set, s.captures, CalibrateOptions{});
    ADD_FAILURE() << "calibrated through an undetermined camera: fx "
                  << out.camera.camera_matrix(0, 0) << " for "
                  << s.rig.intrinsics.camera_matrix(0, 0) << ", sigma "
                  << out.camera_focal_sigma_rel;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("focal length"), std::string::npos) << what;
    EXPECT_NE(what.find("--camera"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace lfd::calib
