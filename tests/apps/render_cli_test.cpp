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

#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"

namespace {

namespace fs = std::filesystem;

using Result = lfd::test::RunResult;
using lfd::test::run_lfd;

const std::string kScene = (lfd::test::project_data() / "scenes" / "demo.ply").string();

fs::path temp_dir() { return lfd::test::scratch_dir("render_cli"); }

TEST(RenderCli, WritesAQuiltWithTheTilingSuffix) {
  const fs::path out = temp_dir() / "quilt.png";
  const Result r = run_lfd("render --scene " + kScene + " --views 8 --cols 4 --rows 2 --size 48x32 --chunks 16 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(temp_dir() / "quilt_qs4x2a1.5.png")) << r.output;
}

TEST(RenderCli, PerViewAndG2lfQuiltsAreComparable) {
  const fs::path a = temp_dir() / "pv_qs3x1a1.png", b = temp_dir() / "g2_qs3x1a1.png";
  ASSERT_EQ(run_lfd("render --scene " + kScene + " --method per-view --views 3 --cols 3 --rows 1 --size 40x40 --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run_lfd("render --scene " + kScene + " --method g2lf --chunks 64 --views 3 --cols 3 --rows 1 --size 40x40 --out " + b.string()).exit_code, 0);
  const Result same = run_lfd("compare " + a.string() + " " + a.string() + " --json");
  ASSERT_EQ(same.exit_code, 0) << same.output;
  EXPECT_TRUE(nlohmann::json::parse(same.output)["identical"].get<bool>());
  const Result diff = run_lfd("compare " + a.string() + " " + b.string() + " --json");
  ASSERT_EQ(diff.exit_code, 0) << diff.output;
  const auto j = nlohmann::json::parse(diff.output);
  EXPECT_GT(j["psnr_db"].get<double>(), 20.0);
  EXPECT_LT(j["ssim"].get<double>(), 1.0);
}

TEST(RenderCli, SingleViewAndCameraFile) {
  const fs::path cam = temp_dir() / "cam.json", out = temp_dir() / "view.png";
  std::ofstream(cam) << R"({"position":[0,0,-3],"look_at":[0,0,0],"up":[0,-1,0],"fov_y_deg":40,"width":24,"height":16})";
  const Result r = run_lfd("render --scene " + kScene + " --camera " + cam.string() + " --view 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out));
}

TEST(RenderCli, BadInputExitsWith2AndNamesTheProblem) {
  const fs::path cam = temp_dir() / "bad_cam.json";
  std::ofstream(cam) << R"({"position":[0,0],"look_at":[0,0,0],"fov_y_deg":40})";
  Result r = run_lfd("render --scene " + kScene + " --camera " + cam.string() + " --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("position"), std::string::npos) << r.output;
  r = run_lfd("render --scene " + kScene + " --filter cubic --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--filter"), std::string::npos) << r.output;
  r = run_lfd("render --scene " + kScene + " --binning disparity --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--binning"), std::string::npos) << r.output;
  r = run_lfd("render --scene /nonexistent.ply --out " + (temp_dir() / "x.png").string());
  EXPECT_EQ(r.exit_code, 2);
  r = run_lfd("compare /nonexistent_a.png /nonexistent_b.png");
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
