// `lfd device list|read` and `--device` on render, interlace and info, through the real program
// on trees built under --root (this machine has no Looking Glass: the real hidapi and libusb code
// runs and finds nothing; the volumes serve the calibrations).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "display/calibration_file.hpp"
#include "display/visual_json.hpp"
#include "tests/support/run_lfd.hpp"
#include "tests/device/device_test_tree.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The 16" Gen2 unit with a tenth of its pixels and DPI (the same lenses per inch), so render
// and interlace are fast; written as the device would, compact and with its own spacing.
std::string small_unit_text() {
  auto j = nlohmann::ordered_json::parse(read_text_file(test::fixture_calibration("LKG-APW92011.visual.json")));
  j["serial"] = "LKG-A0SMALL";
  j["screenW"]["value"] = 384;
  j["screenH"]["value"] = 216;
  j["DPI"]["value"] = 28.3;
  return j.dump(4) + "\r\n";
}

// A tree with the small unit's volume at /media/me/LKG-A0SMALL.
fs::path tree_with_unit(const std::string& name) {
  const fs::path root = test::temp_dir(name) / "root";
  test::put_calibration(root, "/media/me/LKG-A0SMALL", small_unit_text());
  return root;
}

std::string q(const fs::path& p) {
  std::string quoted = "'";
  quoted += p.string();
  quoted += "'";
  return quoted;
}

TEST(DeviceCli, ListOnAnEmptyRootSaysNothingFoundAndWhatToDo) {
  const fs::path root = test::temp_dir("cli_empty");
  const auto r = test::run_lfd("device list --root " + q(root));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no Looking Glass found"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--calibration"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(root.string()), std::string::npos) << r.output;
}

TEST(DeviceCli, ListShowsAUnitItsSourceAndPanel) {
  const fs::path root = tree_with_unit("cli_list");
  const auto r = test::run_lfd("device list --root " + q(root));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("LKG-A0SMALL: USB volume at /media/me/LKG-A0SMALL/LKG_calibration/visual.json"),
            std::string::npos) << r.output;
  EXPECT_NE(r.output.find("readable, panel 384x216"), std::string::npos) << r.output;

  const auto j = test::run_lfd("device list --json --root " + q(root));
  ASSERT_EQ(j.exit_code, 0) << j.output;
  const auto parsed = nlohmann::json::parse(j.output);
  ASSERT_EQ(parsed["devices"].size(), 1u);
  EXPECT_EQ(parsed["devices"][0]["serial"], "LKG-A0SMALL");
  EXPECT_EQ(parsed["devices"][0]["kind"], "usb-volume");
  EXPECT_EQ(parsed["devices"][0]["readable"], true);
}

TEST(DeviceCli, ListReportsAnUnreadableUnitWithTheReason) {
  const fs::path root = test::temp_dir("cli_unreadable") / "root";
  fs::create_directories(root / "media/me/LKG-P00655/LKG_calibration/visual.json");
  const auto r = test::run_lfd("device list --root " + q(root));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("not readable: cannot read"), std::string::npos) << r.output;
}

TEST(DeviceCli, ReadWritesTheServedCalibrationAndVisualJsonByteForByte) {
  const fs::path root = tree_with_unit("cli_read");
  const fs::path out = root.parent_path() / "out";
  const auto r = test::run_lfd("device read --root " + q(root) + " --out " + q(out / "cal.json") +
                               " --visual-json " + q(out / "visual.json"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(bytes_of(out / "visual.json"), small_unit_text());
  const display::Calibration read = display::read_calibration(out / "cal.json");
  const display::DisplayCalibration served = display::parse_visual_json(small_unit_text(), "served");
  EXPECT_EQ(display::to_visual_json(read.display), display::to_visual_json(served));
  EXPECT_EQ(read.provenance["device"]["serial"], "LKG-A0SMALL");
}

TEST(DeviceCli, ReadFailuresWriteNothing) {
  const fs::path root = tree_with_unit("cli_read_fail");
  fs::create_directories(root / "media/me/LKG-P00655/LKG_calibration/visual.json");  // unreadable
  const fs::path out = root.parent_path() / "out";
  for (const std::string serial : {"LKG-NOPE", "LKG-P00655"}) {
    const auto r = test::run_lfd("device read --root " + q(root) + " --serial " + serial +
                                 " --out " + q(out / "cal.json") + " --visual-json " + q(out / "v.json"));
    EXPECT_EQ(r.exit_code, 2) << serial << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out / "cal.json"));
    EXPECT_FALSE(fs::exists(out / "v.json"));
  }
  // Only an unreadable unit attached: auto names it and its reason.
  const fs::path lone = test::temp_dir("cli_read_lone") / "root";
  fs::create_directories(lone / "media/me/LKG-P00655/LKG_calibration/visual.json");
  const auto r_auto = test::run_lfd("device read --root " + q(lone) + " --out " + q(out / "cal.json"));
  EXPECT_EQ(r_auto.exit_code, 2) << r_auto.output;
  EXPECT_NE(r_auto.output.find("LKG-P00655"), std::string::npos) << r_auto.output;
  EXPECT_NE(r_auto.output.find("cannot read"), std::string::npos) << r_auto.output;
  EXPECT_FALSE(fs::exists(out / "cal.json"));
  // An existing --visual-json is refused before the calibration is written.
  test::write_file(out / "v.json", "mine");
  const auto r = test::run_lfd("device read --root " + q(root) + " --serial LKG-A0SMALL --out " +
                               q(out / "cal.json") + " --visual-json " + q(out / "v.json"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_FALSE(fs::exists(out / "cal.json"));
  EXPECT_EQ(bytes_of(out / "v.json"), "mine");
}

TEST(DeviceCli, InfoWithDeviceEqualsInfoWithTheFile) {
  const fs::path root = tree_with_unit("cli_info");
  const fs::path file = root.parent_path() / "unit.visual.json";
  test::write_file(file, small_unit_text());
  auto a = test::run_lfd("info --json --device LKG-A0SMALL --root " + q(root));
  EXPECT_NE(a.output.find("using the calibration of LKG-A0SMALL"), std::string::npos) << a.output;
  a.output = a.output.substr(a.output.find('{'));  // after the note on stderr
  const auto b = test::run_lfd("info --json --calibration " + q(file));
  ASSERT_EQ(a.exit_code, 0) << a.output;
  ASSERT_EQ(b.exit_code, 0) << b.output;
  auto ja = nlohmann::json::parse(a.output), jb = nlohmann::json::parse(b.output);
  EXPECT_EQ(ja["file"], "device LKG-A0SMALL");
  ja.erase("file");
  jb.erase("file");
  EXPECT_EQ(ja, jb);
}

TEST(DeviceCli, CalibrationAndDeviceExcludeEachOther) {
  const fs::path root = tree_with_unit("cli_excl");
  const auto r = test::run_lfd("info --device auto --root " + q(root) + " --calibration x.json");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("excludes"), std::string::npos) << r.output;
  const auto none = test::run_lfd("info");
  EXPECT_EQ(none.exit_code, 2) << none.output;
  EXPECT_NE(none.output.find("--calibration is required"), std::string::npos) << none.output;
}

TEST(DeviceCli, RenderAndInterlaceWithDeviceEqualThemWithTheFile) {
  const fs::path root = tree_with_unit("cli_render");
  const fs::path dir = root.parent_path();
  const fs::path file = dir / "unit.visual.json";
  test::write_file(file, small_unit_text());
  const std::string scene = (test::project_data() / "scenes" / "demo.ply").string();
  const std::string common = "render --scene " + q(scene) + " --size 48x27 --chunks 8 --views 8 ";
  const auto a = test::run_lfd(common + "--device LKG-A0SMALL --root " + q(root) + " --panel " +
                               q(dir / "a_panel.png") + " --out " + q(dir / "a" / "q.png"));
  ASSERT_EQ(a.exit_code, 0) << a.output;
  EXPECT_NE(a.output.find("display device LKG-A0SMALL"), std::string::npos) << a.output;
  const auto b = test::run_lfd(common + "--calibration " + q(file) + " --panel " +
                               q(dir / "b_panel.png") + " --out " + q(dir / "b" / "q.png"));
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_EQ(bytes_of(dir / "a_panel.png"), bytes_of(dir / "b_panel.png"));

  fs::path quilt;
  for (const auto& e : fs::directory_iterator(dir / "b")) quilt = e.path();
  const auto c = test::run_lfd("interlace --device auto --root " + q(root) + " --quilt " + q(quilt) +
                               " --out " + q(dir / "c_panel.png"));
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const auto d = test::run_lfd("interlace --calibration " + q(file) + " --quilt " + q(quilt) +
                               " --out " + q(dir / "d_panel.png"));
  ASSERT_EQ(d.exit_code, 0) << d.output;
  EXPECT_EQ(bytes_of(dir / "c_panel.png"), bytes_of(dir / "d_panel.png"));
}

TEST(DeviceCli, PatternsWithDeviceEqualPatternsWithTheFile) {
  if (test::run_lfd("patterns --help").exit_code != 0) GTEST_SKIP() << "renderer-only lfd: no patterns";
  const fs::path root = tree_with_unit("cli_patterns");
  const fs::path dir = root.parent_path();
  const fs::path file = dir / "unit.visual.json";
  test::write_file(file, small_unit_text());
  const auto a = test::run_lfd("patterns --device auto --root " + q(root) + " --out " + q(dir / "a"));
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const auto b = test::run_lfd("patterns --display " + q(file) + " --out " + q(dir / "b"));
  ASSERT_EQ(b.exit_code, 0) << b.output;
  size_t compared = 0;
  for (const auto& e : fs::directory_iterator(dir / "b" / "patterns")) {
    if (e.path().extension() != ".png") continue;
    EXPECT_EQ(bytes_of(e.path()), bytes_of(dir / "a" / "patterns" / e.path().filename())) << e.path();
    ++compared;
  }
  EXPECT_GT(compared, 10u);
}

TEST(DeviceCli, RenderWithDeviceOnAnEmptyRootSaysNothingFound) {
  const fs::path root = test::temp_dir("cli_render_none");
  const std::string scene = (test::project_data() / "scenes" / "demo.ply").string();
  const auto r = test::run_lfd("render --scene " + q(scene) + " --device auto --root " + q(root) +
                               " --out " + q(root / "q.png"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no Looking Glass found"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace lfd
