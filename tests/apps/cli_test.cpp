// Runs the real `lfd` program: exit codes and one-line errors for bad usage and bad input,
// and that nothing is written on failure.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_lfd.hpp"

#include <nlohmann/json.hpp>

#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace {

using Result = lfd::test::RunResult;

using lfd::test::run_lfd;

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

TEST(Cli, HelpExitsZeroAndUnknownCommandTwo) {
  EXPECT_EQ(run_lfd("--help").exit_code, 0);
  EXPECT_EQ(run_lfd("info --help").exit_code, 0);
  EXPECT_EQ(run_lfd("frobnicate").exit_code, 2);
  EXPECT_EQ(run_lfd("").exit_code, 2);
}

TEST(Cli, MissingRequiredOptionIsExitTwo) {
  Result r = run_lfd("interlace --quilt q.png");  // neither --calibration nor --out
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("required"), std::string::npos) << r.output;
  const auto out = lfd::test::temp_dir("cli_missing_option") / "panel.png";
  r = run_lfd("interlace --quilt q.png --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--calibration"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// lfd bench render's --size: N or WxH (the paper's 512x910); anything else is one line, exit 2,
// before a scene is made.
TEST(Cli, BenchRenderSizeIsNOrWxH) {
  for (const char* bad : {"512x", "512x910x2", "wide", "0x512", "512.5"}) {
    const Result r = run_lfd(std::string("bench render --generated 10 --size ") + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
    EXPECT_EQ(lines(r.output), 1) << r.output;
  }
  const Result r = run_lfd("bench render --generated 10 --size 512x8");  // a side under 16
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("512x8"), std::string::npos) << r.output;
}

TEST(Cli, MissingCalibrationFileIsNamed) {
  const Result r = run_lfd("info --calibration /nonexistent/unit.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("/nonexistent/unit.json"), std::string::npos) << r.output;
  EXPECT_EQ(lines(r.output), 1) << r.output;
}

TEST(Cli, BadCalibrationFieldIsNamed) {
  const auto dir = lfd::test::temp_dir("cli_bad_field");
  std::ofstream(dir / "bad.json")
      << R"({"pitch":{"value":50},"slope":{"value":0},"center":{"value":0},"DPI":{"value":283},"screenW":{"value":64},"screenH":{"value":32}})";
  const Result r = run_lfd("info --calibration " + (dir / "bad.json").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("slope"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
}

TEST(Cli, InterlaceWritesAPanelOfTheDisplaySizeAndNothingOnFailure) {
  const auto dir = lfd::test::temp_dir("cli_interlace");
  std::ofstream(dir / "unit.json")
      << R"({"pitch":{"value":50},"slope":{"value":-7},"center":{"value":0.2},"DPI":{"value":283},"screenW":{"value":96},"screenH":{"value":64}})";
  lfd::write_png(dir / "q_qs4x2a1.5.png", lfd::Image8(120, 40, 3, 128));
  Result r = run_lfd("interlace --calibration " + (dir / "unit.json").string() + " --quilt " +
                 (dir / "q_qs4x2a1.5.png").string() + " --out " + (dir / "panel.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const lfd::Image8 panel = lfd::read_image(dir / "panel.png");
  EXPECT_EQ(panel.width, 96);
  EXPECT_EQ(panel.height, 64);

  // A quilt whose name carries no tiling: exit 2, the file named, no output.
  lfd::write_png(dir / "plain.png", lfd::Image8(120, 40, 3, 128));
  r = run_lfd("interlace --calibration " + (dir / "unit.json").string() + " --quilt " +
          (dir / "plain.png").string() + " --out " + (dir / "panel2.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("plain.png"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "panel2.png"));

  // More views than tiles.
  r = run_lfd("interlace --calibration " + (dir / "unit.json").string() + " --quilt " +
          (dir / "q_qs4x2a1.5.png").string() + " --views 9 --out " + (dir / "panel3.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "panel3.png"));
}

TEST(Cli, InfoReportsDerivedFiguresAsJson) {
  const Result r = run_lfd("info --json --calibration " +
                       (lfd::test::fixture_calibration("LKG-APW92011.visual.json")).string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_NEAR(j["lens"]["lenses_across_screen"].get<double>(), 673.4608856975016, 1e-9);
  // atan(1 / slope) in degrees, slope -7.521984: -7.5727.
  EXPECT_NEAR(j["lens"]["slant_deg"].get<double>(), -7.5727, 1e-3);
  EXPECT_GT(j["recommended_views"]["views"].get<int>(), 0);
  EXPECT_FALSE(j["recommended_views"]["rule"].get<std::string>().empty());
}

}  // namespace
