// The live loop (`lfd calibrate --live --simulate TRUTH.json`): rounds of patterns made for the
// previous estimate, "shown" to the simulator; later rounds start closer to the truth.
#include <gtest/gtest.h>

#include "calib/live_calibration.hpp"
#include "calib/synthetic_unit.hpp"
#include "calib/visual_json.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

TEST(CalibrateLive, SimulatedRoundsRefineTheNominalModel) {
  const SyntheticUnit unit = make_synthetic_unit(read_visual_json(
      std::filesystem::path(LFD_SOURCE_DIR) / ".." / "shared" / "data" / "calibrations" /
      "LKG-PORT-portrait.visual.json"));
  LiveOptions o;
  o.rounds = 2;
  o.positions = 2;  // two distances: the view cone is measured, not assumed
  o.capture_width_px = 480;
  std::vector<CalibrationErrors> errors;
  o.on_round = [&](int, const CalibrationOutcome& out) {
    errors.push_back(compare_with_truth(out.calibration, unit.truth));
  };
  const CalibrationErrors before = compare_with_truth(unit.nominal, unit.truth);
  const CalibrationOutcome out = run_live_calibration_simulated(unit.nominal, unit.truth, o);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_LT(errors[0].phase_rms_periods, 0.2 * before.phase_rms_periods);
  EXPECT_LT(errors[1].phase_rms_periods, 0.2 * before.phase_rms_periods);
  EXPECT_LT(errors[1].pitch_rel, 3e-4);
  EXPECT_LT(errors[1].slant_deg, 0.005);
  EXPECT_TRUE(out.gate_failures.empty());
}

TEST(CalibrateLive, HardwareModeSaysItIsNotAvailable) {
  EXPECT_THROW(run_live_calibration_on_hardware(Calibration{}, LiveOptions{}), InputError);
}

}  // namespace
}  // namespace lfd::calib
