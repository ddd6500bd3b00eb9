// The calibration's report on the console (serve/calibration_report_summary.hpp): found beside an
// lfd calibration.json where lfd calibrate's examples put it, summed up, refused in one line
// naming the file and field when it is not a report; none for a factory calibration.
#include <fstream>

#include <gtest/gtest.h>

#include "serve/calibration_report_summary.hpp"
#include "tests/serve/serve_test_support.hpp"
#include "util/error.hpp"

namespace lfd::serve {
namespace {

constexpr const char* kReport = R"({
  "calibration": {"format": "lfd-calibration", "display": {"viewCone": {"value": 39.6}},
                  "residuals": {"rms_periods": 0.0125}},
  "positions": [{"name": "left"}, {"name": "centre"}, {"name": "right"}],
  "solver": {"termination": "CONVERGENCE", "residual_robust_sigma_periods": 0.011},
  "warnings": ["the cover layer was assumed"], "gate_failures": [], "seconds": 41.5})";

void write(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

ServedDisplay calibrated_in(const std::filesystem::path& folder) {
  ServedDisplay d = test::fixture_display();
  d.calibration_source = "lfd calibration.json";
  d.calibration_path = folder / "calibration.json";
  return d;
}

TEST(CalibrationReport, FoundBesideAnLfdCalibrationAndSummedUp) {
  test::TempDir dir;
  const ServedDisplay d = calibrated_in(dir.path / "unit42");
  EXPECT_FALSE(find_calibration_report(d)) << "no report written yet";
  write(dir.path / "unit42" / "report" / "report.json", kReport);
  write(dir.path / "unit42" / "report" / "index.html", "<html></html>");
  const auto file = find_calibration_report(d);
  ASSERT_TRUE(file);
  EXPECT_EQ(*file, dir.path / "unit42" / "report" / "report.json");
  const nlohmann::json s = calibration_report_summary(*file);
  EXPECT_TRUE(s["accepted"].get<bool>());
  EXPECT_EQ(s["positions"], 3);
  EXPECT_EQ(s["warnings"], nlohmann::json::array({"the cover layer was assumed"}));
  EXPECT_DOUBLE_EQ(s["residual_rms_periods"].get<double>(), 0.0125);
  EXPECT_DOUBLE_EQ(s["view_cone_deg"].get<double>(), 39.6);
  EXPECT_EQ(s["termination"], "CONVERGENCE");
  EXPECT_EQ(s["page"], (dir.path / "unit42" / "report" / "index.html").string());
}

TEST(CalibrationReport, ARefusedCalibrationSaysWhichGates) {
  test::TempDir dir;
  write(dir.path / "report.json", R"({"calibration": {}, "solver": {}, "gate_failures": ["view cone: far from nominal"]})");
  const nlohmann::json s = calibration_report_summary(dir.path / "report.json");
  EXPECT_FALSE(s["accepted"].get<bool>());
  EXPECT_EQ(s["gate_failures"][0], "view cone: far from nominal");
  EXPECT_TRUE(s["residual_rms_periods"].is_null());
  EXPECT_TRUE(s["page"].is_null());
  // Beside the calibration itself (no report folder) is the second place looked at.
  EXPECT_EQ(find_calibration_report(calibrated_in(dir.path)), dir.path / "report.json");
}

TEST(CalibrationReport, AFactoryCalibrationHasNone) {
  test::TempDir dir;
  write(dir.path / "report" / "report.json", kReport);
  ServedDisplay d = test::fixture_display();
  d.calibration_path = dir.path / "visual.json";  // factory visual.json: lfd calibrate wrote nothing
  EXPECT_FALSE(find_calibration_report(d));
}

TEST(CalibrationReport, WhatIsNotAReportIsRefusedNamingFileAndField) {
  test::TempDir dir;
  const auto file = dir.path / "report.json";
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {"{not json", "report.json"},
           {R"({"positions": []})", "not a report of lfd calibrate"},
           {R"({"calibration": {}, "solver": {}, "gate_failures": "none"})", "gate_failures"},
           {R"({"calibration": {}, "solver": {"termination": 3}})", "solver.termination"},
           {R"({"calibration": {}, "solver": {}, "warnings": [1]})", "warnings"}}) {
    write(file, text);
    try {
      calibration_report_summary(file);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(file.string()), std::string::npos) << what;
      EXPECT_NE(what.find(says), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  EXPECT_THROW(calibration_report_summary(dir.path / "missing.json"), InputError);
}

}  // namespace
}  // namespace lfd::serve
