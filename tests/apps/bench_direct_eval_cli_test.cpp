// The evaluation commands of direct panel rendering (docs/rendering.md "Photographs between two
// quilt views", "Per-view direct: the baseline") end to end on a small display: `lfd bench direct
// --baseline` (per-view direct: its panel is the per-view panel exactly) and `lfd bench
// direct-photos` (photographs between two quilt views); bad options are one line and exit 2.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/run_lfd.hpp"
#include "tests/support/small_displays.hpp"
#include "tests/test_data.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

const std::string kScene = (test::project_data() / "scenes" / "demo.ply").string();

// LKG-2K's lens on a 320x200 panel, with the fringe gain (tests/support/small_displays.hpp).
std::string small_display(const fs::path& dir) {
  const fs::path path = dir / "small.visual.json";
  std::ofstream(path) << test::small_lkg_2k_visual_json(0.1);
  return path.string();
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(BenchDirectEvalCli, BaselinePanelIsThePerViewPanelAndTheMaskLeavesOutPixels) {
  const fs::path dir = test::temp_dir("bench_direct_baseline");
  const std::string json = (dir / "b.json").string();
  // Views of 160 rows for a 200-row panel: the panel cannot read every pixel of 16 views.
  const auto r = test::run_lfd("bench direct --baseline --calibration " + small_display(dir) + " --scene " + kScene +
                               " --generated 0 --view-height 160 --baseline-views 16 --chunks 16 --runs 1 --warmup 0"
                               " --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = read_json(json);
  ASSERT_EQ(j["rows"].size(), 1u);
  const auto& row = j["rows"][0];
  EXPECT_EQ(row["views"], 16);
  EXPECT_EQ(row["max_panel_difference"].get<double>(), 0.0);
  EXPECT_GT(row["fraction_masked_in"].get<double>(), 0.05);
  EXPECT_LT(row["fraction_masked_in"].get<double>(), 0.95);
}

TEST(BenchDirectEvalCli, PhotosScoreEveryPathAtEveryEye) {
  const fs::path dir = test::temp_dir("bench_direct_photos");
  const std::string json = (dir / "p.json").string();
  const auto r = test::run_lfd("bench direct-photos --calibration " + small_display(dir) + " --scene " + kScene +
                               " --generated 0 --view-height 64 --chunks 16 --eye-views 2,4 --eye-between 0,0.5"
                               " --photo-width 48 --supersample 1 --json " + json);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = read_json(json);
  ASSERT_EQ(j["tables"].size(), 1u);
  const auto& eyes = j["tables"][0]["eyes"];
  ASSERT_EQ(eyes.size(), 4u);
  const int views = j["tables"][0]["views"];
  for (const auto& e : eyes) {
    EXPECT_DOUBLE_EQ(e["fraction"].get<double>(), (e["view"].get<int>() + 0.5 + e["between"].get<double>()) / views);
    for (const char* k : {"psnr_direct_db", "psnr_quilt_nearest_db", "psnr_quilt_linear_db",
                          "psnr_per_view_quilt_nearest_db", "psnr_per_view_quilt_linear_db"}) {
      ASSERT_TRUE(e[k].is_number()) << k;
      EXPECT_GT(e[k].get<double>(), 15.0) << k;  // the photographs show the scene, not noise
    }
  }
}

TEST(BenchDirectEvalCli, BadOptionsAreOneLineAndExitTwo) {
  const fs::path dir = test::temp_dir("bench_direct_eval_bad");
  const std::string display = small_display(dir);
  for (const std::string& args :
       {"bench direct --baseline --backend gl --calibration " + display,
        "bench direct --baseline --baseline-views 300 --calibration " + display,
        "bench direct-photos --eye-between 1 --calibration " + display,
        "bench direct-photos --supersample 0 --calibration " + display}) {
    const auto r = test::run_lfd(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace lfd
