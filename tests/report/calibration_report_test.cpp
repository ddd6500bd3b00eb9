// The calibration report (`lfd calibrate --report DIR`): report.json, gnuplot figures and an
// HTML page, written for passed and for rejected calibrations.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sim/synthetic_unit.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"
#include "report/calibration_report.hpp"

namespace lfd::report {
namespace {

namespace fs = std::filesystem;

bool has_gnuplot() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }

#define REQUIRE_GNUPLOT()                                                        \
  do {                                                                           \
    if (!has_gnuplot()) GTEST_SKIP() << "gnuplot (gnuplot-nox) is not installed"; \
  } while (0)

std::string read_file(const fs::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// The images a page shows, in order.
std::vector<std::string> image_sources(const std::string& html) {
  std::vector<std::string> out;
  const std::regex src("<img src=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), src); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[1]);
  return out;
}

// A solved outcome made by hand: a portrait panel, two positions (one with a space in its
// name), decoded phase that wraps a few times, residuals of 0.02 period with 5 % outliers.
calib::CalibrationOutcome outcome_with_two_positions() {
  calib::CalibrationOutcome o;
  auto& c = o.calibration;
  c.display.screen_w = 1536;
  c.display.screen_h = 2048;
  c.display.dpi = 324;
  c.display.pitch_lpi = 52.5;
  c.display.slope = -7.2;
  c.view_cone_measured_deg = 41.3;
  c.uncertainty = {{"pitch_lpi", 1e-4}, {"slope", 2e-4}, {"slant_deg", 2e-4},
                   {"center_periods", 0.002}, {"view_cone_deg", 0.3},
                   {"correction_rms_periods", 0.004}};
  std::vector<double> coefficients(64);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) coefficients[size_t(j * 8 + i)] = 0.1 * std::sin(i * 0.7 + j * 0.4);
  c.correction = display::CorrectionField(8, 8, coefficients);
  c.recommended_views = 48;
  c.view_count_rule = "views = min(sampling, blur, accuracy)";
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.f, 0.02f);
  std::uniform_real_distribution<float> uniform(-0.5f, 0.5f);
  for (const char* name : {"near", "far left"}) {
    calib::PositionReport p;
    p.name = name;
    p.board_corners = 40;
    p.camera_m = {0.05, 0.0, 0.6};
    p.camera_refined_m = {0.051, 0.0, 0.601};
    std::vector<calib::ResidualSample> samples;
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 60; ++x) {
        const float u = (x + 0.5f) / 60, v = (y + 0.5f) / 80;
        const float psi = 3.1f * u + 1.7f * v;
        const float r = (x * 7 + y * 13) % 20 == 0 ? uniform(rng) : noise(rng);
        samples.push_back({u, v, psi - std::floor(psi), r});
      }
    p.samples = long(samples.size());
    p.residual_rms_periods = 0.02;
    o.positions.push_back(p);
    o.solve.position_samples.push_back(samples);
    o.solve.position_rms.push_back(0.02);
  }
  o.solve.residuals = {0.02, 0.014, 0.95, 9600};
  o.solve.converged = true;
  o.solve.report = "stage 1: Ceres Solver Report: Iterations: 12, Termination: CONVERGENCE";
  return o;
}

TEST(CalibrationReport, PageNamesEveryPositionAndFigure) {
  REQUIRE_GNUPLOT();
  const fs::path dir = test::temp_dir("calibration_report_page");
  const fs::path index = write_calibration_report(outcome_with_two_positions(), dir);
  ASSERT_EQ(index, dir / "index.html");
  const std::string html = read_file(index);
  for (const char* name : {"near", "far left"}) EXPECT_NE(html.find(name), std::string::npos);
  const std::vector<std::string> expected = {"p1_near_psi.png", "p1_near_residual.png",
                                             "p2_far_left_psi.png", "p2_far_left_residual.png",
                                             "correction.png", "residual_histogram.png"};
  EXPECT_EQ(image_sources(html), expected);
  EXPECT_NE(html.find("Every quality gate passed"), std::string::npos);
  EXPECT_NE(html.find("52.50000"), std::string::npos) << "the pitch";
  EXPECT_NE(html.find("Recommended views: 48"), std::string::npos);
  fs::remove_all(dir);
}

// With the unit's factory calibration (from --device or --display), the page and report.json
// compare the recovered lens with it: the differences, and in units of the recovered sigmas.
TEST(CalibrationReport, ComparesWithTheFactoryCalibration) {
  const calib::CalibrationOutcome outcome = outcome_with_two_positions();
  ReferenceCalibration factory{outcome.calibration, "the factory calibration (device TEST-1)"};
  factory.calibration.display.pitch_lpi = outcome.calibration.display.pitch_lpi - 0.25;
  factory.calibration.display.center_periods = outcome.calibration.display.center_periods + 0.98;
  const fs::path dir = test::temp_dir("calibration_report_factory");
  write_calibration_report(outcome, dir, &factory);
  const std::string html = read_file(dir / "index.html");
  EXPECT_NE(html.find("Against the factory calibration (device TEST-1)"), std::string::npos);
  EXPECT_NE(html.find("+0.25000"), std::string::npos) << "the pitch difference";
  EXPECT_NE(html.find("+0.0200"), std::string::npos) << "the center difference, modulo 1";
  const auto j = nlohmann::json::parse(read_file(dir / "report.json"));
  EXPECT_EQ(j["reference"]["name"], "the factory calibration (device TEST-1)");
  // Without one the page has no comparison.
  write_calibration_report(outcome, dir);
  EXPECT_EQ(read_file(dir / "index.html").find("Against"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CalibrationReport, EveryFigureOnThePageIsAReadablePng) {
  REQUIRE_GNUPLOT();
  const fs::path dir = test::temp_dir("calibration_report_png");
  write_calibration_report(outcome_with_two_positions(), dir);
  const auto sources = image_sources(read_file(dir / "index.html"));
  ASSERT_FALSE(sources.empty());
  for (const auto& src : sources) {
    ASSERT_TRUE(fs::exists(dir / src)) << src;
    EXPECT_GT(fs::file_size(dir / src), 0u) << src;
    const Image8 image = read_image(dir / src);
    EXPECT_GE(image.width, 300) << src;
    EXPECT_GE(image.height, 300) << src;
    EXPECT_FALSE(fs::exists(dir / (src + ".tmp"))) << src;
  }
  fs::remove_all(dir);
}

TEST(CalibrationReport, JsonHasThePositionsAndTheFigures) {
  const fs::path dir = test::temp_dir("calibration_report_json");
  write_calibration_report(outcome_with_two_positions(), dir);
  std::ifstream f(dir / "report.json");
  const auto j = nlohmann::json::parse(f);
  ASSERT_EQ(j["positions"].size(), 2u);
  EXPECT_EQ(j["positions"][0]["name"], "near");
  EXPECT_EQ(j["positions"][1]["name"], "far left");
  EXPECT_EQ(j["positions"][1]["phase_samples"], 4800);
  EXPECT_TRUE(j["gate_failures"].empty());
  if (has_gnuplot()) {
    EXPECT_EQ(j["figures"].size(), 6u);
  }
  fs::remove_all(dir);
}

TEST(CalibrationReport, RejectedCalibrationListsEveryFailedGate) {
  calib::CalibrationOutcome o = outcome_with_two_positions();
  o.gate_failures = {"phase residual rms 0.120 > 0.080 lens periods: focus on the screen",
                     "view cone uncertainty 3.10 deg > 2.00: photograph from positions at "
                     "clearly different distances"};
  const fs::path dir = test::temp_dir("calibration_report_rejected");
  write_calibration_report(o, dir);
  const std::string html = read_file(dir / "index.html");
  EXPECT_NE(html.find("Rejected: 2 gates failed"), std::string::npos);
  EXPECT_NE(html.find("<li>phase residual rms 0.120 &gt; 0.080 lens periods: focus on the "
                      "screen</li>"),
            std::string::npos);
  EXPECT_NE(html.find("clearly different distances</li>"), std::string::npos);
  EXPECT_EQ(html.find("Every quality gate passed"), std::string::npos);
  std::ifstream f(dir / "report.json");
  EXPECT_EQ(nlohmann::json::parse(f)["gate_failures"].size(), 2u);
  fs::remove_all(dir);
}

TEST(CalibrationReport, WithoutGnuplotThePageSaysSoAndShowsNoFigure) {
  const fs::path dir = test::temp_dir("calibration_report_no_gnuplot");
  const fs::path empty_bin = dir / "empty_bin";
  fs::create_directories(empty_bin);
  const char* old_path = std::getenv("PATH");
  const std::string saved = old_path ? old_path : "";
  setenv("PATH", empty_bin.c_str(), 1);  // the shell finds no gnuplot
  write_calibration_report(outcome_with_two_positions(), dir);
  setenv("PATH", saved.c_str(), 1);
  const std::string html = read_file(dir / "index.html");
  EXPECT_NE(html.find("Figures not drawn"), std::string::npos);
  EXPECT_TRUE(image_sources(html).empty());
  EXPECT_FALSE(fs::exists(dir / "correction.png"));
  EXPECT_FALSE(fs::exists(dir / "correction.png.tmp"));
  std::ifstream f(dir / "report.json");
  EXPECT_TRUE(nlohmann::json::parse(f)["figures"].empty());
  fs::remove_all(dir);
}

// The real pipeline at the calibration tests' smallest settings (Portrait, 480 px, two
// positions), with a residual gate no photograph can pass: the report of a rejection shows the
// figures of every position and names the gate.
TEST(CalibrationReport, SimulatedRejectedCalibrationHasFiguresForEveryPosition) {
  REQUIRE_GNUPLOT();
  const sim::SyntheticUnit unit = sim::make_synthetic_unit(
      display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json")));
  const sim::PatternSet set = sim::plan_patterns(unit.nominal);
  const sim::CaptureRig rig = sim::make_capture_rig(unit.truth.display, 480, 2);
  calib::CalibrateOptions options;
  options.camera = rig.intrinsics;
  options.gates.max_residual_rms_periods = 1e-6;
  const calib::CalibrationOutcome out =
      calib::calibrate_display(set, sim::simulate_captures(set, unit.truth, rig), options);
  ASSERT_FALSE(out.gate_failures.empty());
  const fs::path dir = test::temp_dir("calibration_report_simulated");
  write_calibration_report(out, dir);
  const std::string html = read_file(dir / "index.html");
  EXPECT_NE(html.find("phase residual rms"), std::string::npos);
  const auto sources = image_sources(html);
  EXPECT_EQ(sources.size(), 2 * out.positions.size() + 2);
  for (const auto& p : out.positions) {
    EXPECT_NE(html.find("<h3>" + p.name + "</h3>"), std::string::npos) << p.name;
    EXPECT_GT(p.samples, 0);
  }
  for (const auto& src : sources) EXPECT_GT(read_image(dir / src).width, 0) << src;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lfd::report
