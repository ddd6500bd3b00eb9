// `lfd render` and `lfd compare` end to end through the real program (small images of the
// bundled demo scene, data/scenes/demo.ply).
#include <unistd.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/apps/run_lfd.hpp"
#include "tests/test_data.hpp"

namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string out;
};

// Output through a pipe, not a shared log file: CTest runs these tests in parallel.
Result run(const std::string& args) {
  const auto r = lfd::test::run_lfd(args);
  return {r.exit_code, r.output};
}

const std::string kScene = (lfd::test::project_data() / "scenes" / "demo.ply").string();

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("lfd_render_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

TEST(RenderCli, WritesAQuiltWithTheTilingSuffix) {
  const fs::path out = temp_dir() / "quilt.png";
  const Result r = run("render --scene " + kScene + " --views 8 --cols 4 --rows 2 --size 48x32 --chunks 16 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fs::exists(temp_dir() / "quilt_qs4x2a1.5.png")) << r.out;
}

TEST(RenderCli, PerViewAndG2lfQuiltsAreComparable) {
  const fs::path a = temp_dir() / "pv_qs3x1a1.png", b = temp_dir() / "g2_qs3x1a1.png";
  ASSERT_EQ(run("render --scene " + kScene + " --method per-view --views 3 --cols 3 --rows 1 --size 40x40 --out " + a.string()).code, 0);
  ASSERT_EQ(run("render --scene " + kScene + " --method g2lf --chunks 64 --views 3 --cols 3 --rows 1 --size 40x40 --out " + b.string()).code, 0);
  const Result same = run("compare " + a.string() + " " + a.string() + " --json");
  ASSERT_EQ(same.code, 0) << same.out;
  EXPECT_TRUE(nlohmann::json::parse(same.out)["identical"].get<bool>());
  const Result diff = run("compare " + a.string() + " " + b.string() + " --json");
  ASSERT_EQ(diff.code, 0) << diff.out;
  const auto j = nlohmann::json::parse(diff.out);
  EXPECT_GT(j["psnr_db"].get<double>(), 20.0);
  EXPECT_LT(j["ssim"].get<double>(), 1.0);
}

TEST(RenderCli, SingleViewAndCameraFile) {
  const fs::path cam = temp_dir() / "cam.json", out = temp_dir() / "view.png";
  std::ofstream(cam) << R"({"position":[0,0,-3],"look_at":[0,0,0],"up":[0,-1,0],"fov_y_deg":40,"width":24,"height":16})";
  const Result r = run("render --scene " + kScene + " --camera " + cam.string() + " --view 2 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fs::exists(out));
}

TEST(RenderCli, BadInputExitsWith2AndNamesTheProblem) {
  const fs::path cam = temp_dir() / "bad_cam.json";
  std::ofstream(cam) << R"({"position":[0,0],"look_at":[0,0,0],"fov_y_deg":40})";
  Result r = run("render --scene " + kScene + " --camera " + cam.string() + " --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("position"), std::string::npos) << r.out;
  r = run("render --scene " + kScene + " --filter cubic --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--filter"), std::string::npos) << r.out;
  r = run("render --scene " + kScene + " --binning disparity --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("--binning"), std::string::npos) << r.out;
  r = run("render --scene /nonexistent.ply --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.code, 2);
  r = run("compare /nonexistent_a.png /nonexistent_b.png");
  EXPECT_EQ(r.code, 2);
}

}  // namespace
