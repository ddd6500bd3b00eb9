// Dense registration from the fringe patterns: photographs of a simulated unit (all capture
// effects) must give a camera position within a millimetre of the truth, which the board's
// corners alone do not (they leave the lateral position several millimetres off, and with it
// the center).
#include <gtest/gtest.h>

#include "calib/calibrate.hpp"
#include "sim/synthetic_unit.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

TEST(FringeRegistration, PinsTheCameraPositionToAMillimetre) {
  const auto real = display::read_visual_json(lfd::test::fixture_calibration("LKG-APW92011.visual.json"));
  const sim::SyntheticUnit unit = sim::make_synthetic_unit(real);
  const sim::PatternSet set = sim::plan_patterns(unit.nominal);
  ASSERT_EQ(set.of_kind(sim::PatternKind::kFringeX).size(), 4u);
  const sim::CaptureRig rig = sim::make_capture_rig(unit.truth.display, 800, 2, false);
  const auto captures = sim::simulate_captures(set, unit.truth, rig);
  CalibrateOptions options;
  options.camera = rig.intrinsics;
  const CalibrationOutcome out = calibrate_display(set, captures, options);
  ASSERT_EQ(out.positions.size(), 2u);
  for (size_t i = 0; i < out.positions.size(); ++i) {
    const PositionReport& p = out.positions[i];
    const Eigen::Vector3d error = p.camera_m - rig.poses[i].position_m;
    std::printf("%s: %ld fringe points, camera error (%.2f, %.2f, %.2f) mm\n", p.name.c_str(),
                p.fringe_points, 1e3 * error.x(), 1e3 * error.y(), 1e3 * error.z());
    EXPECT_GT(p.fringe_points, 300) << p.name;
    EXPECT_LT(std::abs(error.x()), 1e-3) << p.name;
    EXPECT_LT(std::abs(error.z()), 1e-3) << p.name;
  }
  const sim::CalibrationErrors e = sim::compare_with_truth(out.calibration, unit.truth);
  EXPECT_LT(e.center_periods, 0.005);
}

}  // namespace
}  // namespace lfd::calib
