#include "display/calibration_file.hpp"

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::display {
namespace {

Calibration sample_calibration() {
  Calibration c;
  c.display = parse_visual_json(
      R"({"configVersion":"3.0","serial":"S1","pitch":{"value":50.1},"slope":{"value":-7.5},)"
      R"("center":{"value":0.25},"viewCone":{"value":40},"invView":{"value":1},"DPI":{"value":283},)"
      R"("screenW":{"value":3840},"screenH":{"value":2160}})",
      "mem");
  std::vector<double> coeffs(6 * 5);
  for (size_t i = 0; i < coeffs.size(); ++i) coeffs[i] = 0.01 * double(i % 7) - 0.02;
  c.correction = CorrectionField(6, 5, coeffs);
  c.view_cone_measured_deg = 41.3;
  c.phase_blur_sigma = 0.011;
  c.uncertainty = {{"pitch_lpi", 1e-4}, {"slope", 2e-5}};
  c.residuals = ResidualStats{0.01, 0.007, 0.96, 12345};
  c.recommended_views = 45;
  c.view_count_rule = "rule text";
  c.provenance = {{"tool", "test"}};
  return c;
}

TEST(CalibrationFile, RoundTripsEveryField) {
  const auto dir = test::temp_dir("calibration_roundtrip");
  const Calibration c = sample_calibration();
  write_calibration(dir / "calibration.json", c, false);
  const Calibration r = read_calibration(dir / "calibration.json");
  EXPECT_EQ(r.display.pitch_lpi, c.display.pitch_lpi);
  EXPECT_EQ(r.display.serial, "S1");
  EXPECT_EQ(r.correction.nx(), 6);
  EXPECT_EQ(r.correction.ny(), 5);
  EXPECT_EQ(r.correction.coefficients(), c.correction.coefficients());
  EXPECT_EQ(*r.view_cone_measured_deg, 41.3);
  EXPECT_EQ(*r.phase_blur_sigma, 0.011);
  EXPECT_EQ(r.uncertainty.at("slope"), 2e-5);
  EXPECT_EQ(r.residuals->count, 12345);
  EXPECT_EQ(*r.recommended_views, 45);
  EXPECT_EQ(r.view_count_rule, "rule text");
  EXPECT_EQ(to_json(r).dump(), to_json(c).dump());
}

TEST(CalibrationFile, ReadsAPlainVisualJson) {
  for (const auto& file : test::fixture_calibrations()) {
    const Calibration c = read_calibration(file);
    EXPECT_TRUE(c.correction.empty()) << file;
    EXPECT_GT(c.display.pitch_lpi, 0) << file;
  }
}

TEST(CalibrationFile, NeverOverwritesWithoutForceAndKeepsABackup) {
  const auto dir = test::temp_dir("calibration_force");
  Calibration c = sample_calibration();
  write_calibration(dir / "c.json", c, false);
  c.display.pitch_lpi = 51.0;
  EXPECT_THROW(write_calibration(dir / "c.json", c, false), InputError);
  EXPECT_EQ(read_calibration(dir / "c.json").display.pitch_lpi, 50.1);
  write_calibration(dir / "c.json", c, true);
  EXPECT_EQ(read_calibration(dir / "c.json").display.pitch_lpi, 51.0);
  EXPECT_EQ(read_calibration(dir / "c.json.bak").display.pitch_lpi, 50.1);
}

TEST(CalibrationFile, ExportedVisualJsonHoldsTheLensFields) {
  const auto dir = test::temp_dir("calibration_export");
  const Calibration c = sample_calibration();
  export_visual_json(dir / "visual.json", c, false);
  const DisplayCalibration v = read_visual_json(dir / "visual.json");
  EXPECT_EQ(v.pitch_lpi, 50.1);
  EXPECT_EQ(v.slope, -7.5);
  EXPECT_FALSE(nlohmann::json::parse(read_text_file(dir / "visual.json")).contains("correction"));
}

// A calibration as `lfd calibrate` leaves it: the measured cone replaced the nominal.
Calibration measured_cone_calibration() {
  Calibration c = sample_calibration();
  c.view_cone_nominal_deg = 40.0;
  c.view_cone_measured_deg = 38.5;
  c.display.view_cone_deg = 38.5;
  return c;
}

TEST(CalibrationFile, TheMeasuredConeIsTheConeAndTheNominalIsKept) {
  const auto dir = test::temp_dir("calibration_cone");
  write_calibration(dir / "c.json", measured_cone_calibration(), false);
  const auto j = nlohmann::json::parse(read_text_file(dir / "c.json"));
  EXPECT_EQ(j["display"]["viewCone"]["value"].get<double>(), 38.5);
  EXPECT_EQ(j["view_cone_measured_deg"].get<double>(), 38.5);
  EXPECT_EQ(j["view_cone_nominal_deg"].get<double>(), 40.0);
  const Calibration r = read_calibration(dir / "c.json");
  EXPECT_EQ(r.display.view_cone_deg, 38.5);
  EXPECT_EQ(*r.view_cone_measured_deg, 38.5);
  EXPECT_EQ(*r.view_cone_nominal_deg, 40.0);
}

TEST(CalibrationFile, AnOlderFileWithOnlyTheMeasuredConeReadsWithTheMeasuredCone) {
  // Written before the nominal was kept beside it: display.viewCone holds the nominal.
  auto j = to_json(measured_cone_calibration());
  j["display"]["viewCone"]["value"] = 40.0;
  j.erase("view_cone_nominal_deg");
  const Calibration r = parse_calibration(j.dump(), "old.json");
  EXPECT_EQ(r.display.view_cone_deg, 38.5);
  EXPECT_EQ(*r.view_cone_measured_deg, 38.5);
  EXPECT_EQ(*r.view_cone_nominal_deg, 40.0);
}

TEST(CalibrationFile, AMeasuredConeNotYetInTheDisplayKeepsTheDisplaysConeAsNominal) {
  Calibration c = sample_calibration();  // display 40, measured 41.3, no nominal
  ASSERT_FALSE(c.view_cone_nominal_deg);
  const Calibration r = parse_calibration(to_json(c).dump(), "c.json");
  EXPECT_EQ(r.display.view_cone_deg, 41.3);
  EXPECT_EQ(*r.view_cone_nominal_deg, 40.0);
  // With the display already at the measured cone and no nominal known, none is made up.
  c.display.view_cone_deg = 41.3;
  EXPECT_FALSE(parse_calibration(to_json(c).dump(), "c.json").view_cone_nominal_deg);
}

TEST(CalibrationFile, APlainVisualJsonHasNoMeasuredOrNominalCone) {
  const Calibration c = read_calibration(test::fixture_calibration("LKG-APW92011.visual.json"));
  EXPECT_FALSE(c.view_cone_measured_deg);
  EXPECT_FALSE(c.view_cone_nominal_deg);
  EXPECT_EQ(c.display.view_cone_deg, 40.0);
}

TEST(CalibrationFile, ExportedVisualJsonCarriesTheMeasuredCone) {
  const auto dir = test::temp_dir("calibration_export_cone");
  export_visual_json(dir / "visual.json", measured_cone_calibration(), false);
  EXPECT_EQ(read_visual_json(dir / "visual.json").view_cone_deg, 38.5);
  // Also when the measured cone has not replaced the display's in memory.
  Calibration c = measured_cone_calibration();
  c.display.view_cone_deg = 40.0;
  export_visual_json(dir / "visual2.json", c, false);
  EXPECT_EQ(read_visual_json(dir / "visual2.json").view_cone_deg, 38.5);
}

void expect_rejected(const std::string& text, const std::string& field) {
  try {
    parse_calibration(text, "cal.json");
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cal.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(CalibrationFile, RejectsACorrectionGridOfTheWrongSize) {
  auto j = to_json(sample_calibration());
  j["correction"]["coefficients"].erase(0);
  expect_rejected(j.dump(), "correction.coefficients");
  j = to_json(sample_calibration());
  j["correction"]["nx"] = 2;
  expect_rejected(j.dump(), "correction.nx");
}

TEST(CalibrationFile, RejectsBadValuesInTheSuperset) {
  auto j = to_json(sample_calibration());
  j["version"] = 99;
  expect_rejected(j.dump(), "version");
  j = to_json(sample_calibration());
  j["display"]["pitch"]["value"] = -1;
  expect_rejected(j.dump(), "pitch");
  j = to_json(sample_calibration());
  j["phase_blur_sigma"] = "wide";
  expect_rejected(j.dump(), "phase_blur_sigma");
  j = to_json(sample_calibration());
  j["recommended_views"] = 0;
  expect_rejected(j.dump(), "recommended_views");
}

}  // namespace
}  // namespace lfd::display
