// Round trip (docs/calibration.md section 4): simulate captures of a unit with known truth,
// calibrate, compare with the truth. Reduced capture size so it runs in well under a minute.
#include <cstdlib>

#include <gtest/gtest.h>

#include "calib/calibrate.hpp"
#include "sim/synthetic_unit.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

struct RoundTrip {
  sim::SyntheticUnit unit;
  sim::PatternSet set;
  sim::CaptureRig rig;
  std::vector<sim::PositionCaptures> captures;
};

RoundTrip simulate(const char* file, int width_px, int positions, bool clean) {
  RoundTrip r;
  r.unit = sim::make_synthetic_unit(display::read_visual_json(test::fixture_calibration(file)));
  r.set = sim::plan_patterns(r.unit.nominal);
  r.rig = sim::make_capture_rig(r.unit.truth.display, width_px, positions, clean);
  r.captures = sim::simulate_captures(r.set, r.unit.truth, r.rig);
  return r;
}

TEST(CalibrateRoundTrip, PortraitFromTwoPositionsRecoversLensAndWarp) {
  const RoundTrip r = simulate("LKG-PORT-portrait.visual.json", 480, 2, false);
  CalibrateOptions options;
  options.camera = r.rig.intrinsics;
  const CalibrationOutcome out = calibrate_display(r.set, r.captures, options);
  const sim::CalibrationErrors e = sim::compare_with_truth(out.calibration, r.unit.truth);
  std::printf("slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg, warp %.4f, phase %.4f\n",
              e.slant_deg, e.pitch_rel, e.center_periods, e.view_cone_deg,
              e.correction_rms_periods, e.phase_rms_periods);
  for (const auto& p : r.rig.poses)
    std::printf("true camera %.4f %.4f %.4f\n", p.position_m.x(), p.position_m.y(), p.position_m.z());
  for (const auto& w : out.warnings) std::printf("warning: %s\n", w.c_str());
  for (const auto& f : out.gate_failures) std::printf("gate: %s\n", f.c_str());
  std::printf("%s\n", outcome_report(out).dump(1).c_str());
  EXPECT_LT(e.slant_deg, 0.002);
  EXPECT_LT(e.pitch_rel, 5e-5);
  EXPECT_LT(e.center_periods, 0.01);
  EXPECT_LT(e.view_cone_deg, 1.0);
  EXPECT_LT(e.correction_rms_periods, 0.02);
  EXPECT_TRUE(out.gate_failures.empty());
  // The reported uncertainties are honest: the errors are within a few sigma (and the sigmas
  // are not inflated past use: they pass the gates above).
  const auto& sigma = out.calibration.uncertainty;
  EXPECT_LT(e.center_periods, 4 * sigma.at("center_periods"));
  EXPECT_LT(e.view_cone_deg, 4 * sigma.at("view_cone_deg"));
  EXPECT_LT(e.correction_rms_periods, 4 * sigma.at("correction_rms_periods"));
  EXPECT_LT(e.pitch_rel, 4 * sigma.at("pitch_lpi") / out.calibration.display.pitch_lpi);
}

}  // namespace
}  // namespace lfd::calib
