// The colour-order check inside `lfd calibrate` (docs/calibration.md, 3.7): a BGR unit whose
// description says RGB is refused with the value to give, and with --estimate-colour-order the
// photos' layout is adopted and the accuracy bars of the round trip are met. The round trip's small
// cameras.
#include <cstdio>

#include <gtest/gtest.h>

#include "calib/calibrate.hpp"
#include "display/visual_json.hpp"
#include "sim/synthetic_unit.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

TEST(CalibrateColourOrder, BgrUnitDescribedAsRgbIsRefusedOrEstimated) {
  display::DisplayCalibration real = display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  real.flip_subp = true;  // the truth: a BGR panel
  sim::SyntheticUnit unit = sim::make_synthetic_unit(real);
  unit.nominal.display.flip_subp = false;  // the description: RGB
  const sim::PatternSet set = sim::plan_patterns(unit.nominal);
  const sim::CaptureRig rig = sim::make_capture_rig(unit.truth.display, 480, 2, false);
  const std::vector<sim::PositionCaptures> captures = sim::simulate_captures(set, unit.truth, rig);

  CalibrateOptions options;
  options.camera = rig.intrinsics;
  options.colour_order.estimate = true;
  const CalibrationOutcome adopted = calibrate_display(set, captures, options);
  const sim::CalibrationErrors e = sim::compare_with_truth(adopted.calibration, unit.truth);
  std::printf("%s\nslant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg, warp %.4f\n",
              adopted.colour_order.finding.c_str(), e.slant_deg, e.pitch_rel, e.center_periods,
              e.view_cone_deg, e.correction_rms_periods);
  for (const auto& f : adopted.gate_failures) std::printf("gate: %s\n", f.c_str());
  EXPECT_TRUE(adopted.calibration.display.flip_subp);
  EXPECT_TRUE(adopted.gate_failures.empty());
  EXPECT_LT(e.slant_deg, 0.002);
  EXPECT_LT(e.pitch_rel, 5e-5);
  EXPECT_LT(e.center_periods, 0.01);
  EXPECT_LT(e.view_cone_deg, 1.0);
  EXPECT_LT(e.correction_rms_periods, 0.02);

  options.colour_order.estimate = false;
  const CalibrationOutcome refused = calibrate_display(set, captures, options);
  ASSERT_FALSE(refused.gate_failures.empty());
  EXPECT_NE(refused.gate_failures.back().find("flipSubp is 0, the photos say 1: rerun with "
                                              "--flip-subp 1"),
            std::string::npos)
      << refused.gate_failures.back();
  EXPECT_FALSE(refused.calibration.display.flip_subp);
  // What the wrong layout costs when nothing adopts the right one (reported, not asserted:
  // the gate refuses it anyway).
  const sim::CalibrationErrors w = sim::compare_with_truth(refused.calibration, unit.truth);
  std::printf("refused: slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg, warp %.4f\n",
              w.slant_deg, w.pitch_rel, w.center_periods, w.view_cone_deg,
              w.correction_rms_periods);
}

}  // namespace
}  // namespace lfd::calib
