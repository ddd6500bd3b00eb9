// `lfd demo` end to end, made small (800 px photographs, 64 px tiles, 100 validation points):
// it exits 0 and writes the report with everything the report links, and what it measured
// holds up (the calibration passes its gates; driving the unit with it separates the views
// better than its factory file does).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

bool exists_with_prefix(const fs::path& dir, const std::string& prefix) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(prefix, 0) == 0) return true;
  return false;
}

TEST(DemoCli, ASmallRunWritesTheWholeReport) {
  const fs::path out = test::temp_dir("demo_cli") / "demo";
  const auto r = test::run_lfd("demo --out " + out.string() +
                               " --capture-width 800 --tile-width 64 --points 100");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("report: " + (out / "index.html").string()), std::string::npos) << r.output;

  for (const char* file : {"index.html", "report.json", "unit_truth.calibration.json",
                           "recovered.calibration.json", "scene_panel.png", "numbered_panel.png",
                           "capture_scene_left.png", "capture_scene_centre.png",
                           "capture_scene_right.png", "capture_numbered_left.png",
                           "capture_numbered_centre.png", "capture_numbered_right.png"})
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  EXPECT_TRUE(exists_with_prefix(out, "scene_quilt_qs"));
  EXPECT_TRUE(exists_with_prefix(out, "numbered_quilt_qs"));
  EXPECT_TRUE(fs::is_directory(out / "validation"));

  // Every local file the page links is there.
  const std::string html = read_text_file(out / "index.html");
  for (size_t at = html.find("src=\""); at != std::string::npos; at = html.find("src=\"", at + 1)) {
    const std::string link = html.substr(at + 5, html.find('"', at + 5) - at - 5);
    if (link.find("://") == std::string::npos) EXPECT_TRUE(fs::exists(out / link)) << link;
  }

  const auto report = nlohmann::json::parse(read_text_file(out / "report.json"));
  EXPECT_NE(report["calibration"].get<std::string>().find("Quality gates: passed"), std::string::npos)
      << report["calibration"];
  EXPECT_GE(report["views"].get<int>(), 16);
  double recovered = -1, factory = -1;
  for (const auto& v : report["validation"]) {
    const std::string name = v["configuration"];
    if (name == "recovered calibration") recovered = v["mean_view_separation"];
    if (name.rfind("factory", 0) == 0) factory = v["mean_view_separation"];
  }
  ASSERT_GE(recovered, 0) << report["validation"];
  ASSERT_GE(factory, 0) << report["validation"];
  EXPECT_GT(recovered, factory + 0.1);
}

TEST(DemoCli, BadOptionsExitWith2) {
  const fs::path out = test::temp_dir("demo_cli_bad");
  auto r = test::run_lfd("demo --out " + out.string() + " --capture-width 10");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--capture-width"), std::string::npos) << r.output;
  r = test::run_lfd("demo --out " + out.string() + " --unit /nonexistent.visual.json");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("nonexistent"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace lfd
