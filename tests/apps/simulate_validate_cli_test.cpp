// `lfd simulate`, `lfd validate` and `lfd bench` through the real program (small display).
#include <unistd.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"

#include "util/image.hpp"

namespace {

namespace fs = std::filesystem;

using Result = lfd::test::RunResult;
using lfd::test::run_lfd;

fs::path temp_dir() { return lfd::test::scratch_dir("simulate_cli"); }

// LKG-APW92011's optics at a tenth of the resolution: 384 x 216 pixels, 17 subpixels per lens.
fs::path small_display() {
  const fs::path p = temp_dir() / "small.visual.json";
  std::ofstream(p) << R"({"serial":"small","pitch":{"value":5.00693473815918},
    "slope":{"value":-7.521984100341797},"center":{"value":0.07635253667831421},
    "viewCone":{"value":40.0},"invView":{"value":1.0},"DPI":{"value":28.3},
    "screenW":{"value":384.0},"screenH":{"value":216.0}})";
  return p;
}

fs::path white_panel(int w, int h, const std::string& name) {
  const fs::path p = temp_dir() / name;
  lfd::write_png(p, lfd::Image8(w, h, 3, 255));
  return p;
}

TEST(SimulateCli, WritesACaptureOfTheRequestedSize) {
  const fs::path out = temp_dir() / "capture.png";
  fs::remove(out);
  const Result r = run_lfd("simulate --calibration " + small_display().string() + " --panel " +
                       white_panel(384, 216, "white.png").string() +
                       " --camera-pos 0.02,0.01,0.6 --fov 40 --size 160x90 --supersample 2"
                       " --noise 0.01 --seed 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const lfd::Image8 img = lfd::read_image(out);
  EXPECT_EQ(img.width, 160);
  EXPECT_EQ(img.height, 90);
}

TEST(SimulateCli, PanelOfTheWrongSizeExitsTwoNamingTheFile) {
  const fs::path panel = white_panel(200, 100, "wrong_size.png");
  const Result r = run_lfd("simulate --calibration " + small_display().string() + " --panel " +
                       panel.string() + " --camera-pos 0,0,0.6 --size 64x36 --out " +
                       (temp_dir() / "never.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("wrong_size.png"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(temp_dir() / "never.png"));
}

TEST(SimulateCli, MissingCameraFileExitsTwo) {
  const Result r = run_lfd("simulate --calibration " + small_display().string() + " --panel " +
                       white_panel(384, 216, "white.png").string() +
                       " --camera-pos 0,0,0.6 --camera /nonexistent/cam.yaml --out " +
                       (temp_dir() / "never.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("cam.yaml"), std::string::npos) << r.output;
}

TEST(ValidateCli, ReportsSeparationAsJsonAndWritesTheReport) {
  const fs::path dir = temp_dir() / "report";
  fs::remove_all(dir);
  const Result r = run_lfd("validate --calibration " + small_display().string() +
                       " --views 16 --points 60 --angles-per-view 3 --json --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output.substr(r.output.find('[')));
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["views"].get<int>(), 16);
  EXPECT_GT(j[0]["mean_separation"].get<double>(), 0.6);
  EXPECT_TRUE(fs::exists(dir / "validation.json"));
  EXPECT_TRUE(fs::exists(dir / "index.html"));
}

TEST(ValidateCli, MissingAssumedCalibrationExitsTwo) {
  const Result r = run_lfd("validate --calibration " + small_display().string() +
                       " --assumed /nonexistent/assumed.json --out " +
                       (temp_dir() / "r2").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("assumed.json"), std::string::npos) << r.output;
}

TEST(BenchCli, UnknownBenchmarkExitsTwo) {
  EXPECT_EQ(run_lfd("bench no-such-benchmark").exit_code, 2);
  EXPECT_EQ(run_lfd("bench --help").exit_code, 0);
}

}  // namespace
