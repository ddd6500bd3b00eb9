// `lfd render --calibration F` end to end: the display file (a plain visual.json or the
// calibration.json `lfd calibrate` writes) decides views, tile grid and view cone, the program
// says what it chose, --views overrides the recommendation, and --panel writes the same panel
// as `lfd interlace` of the written quilt. Tiny views of the bundled demo scene, and a small
// panel (a 16" Gen2 scaled to 384x216 with the same optics per lens) so the tests are fast.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

const std::string kScene = (test::project_data() / "scenes" / "demo.ply").string();
const std::string kRenderSmall = " --size 48x27 --chunks 8 ";

// The 16" Gen2 unit's visual.json with a tenth of its pixels and DPI (same lenses per inch of
// panel): what the interlacer does per lens is unchanged, the panel is 100 times smaller.
nlohmann::ordered_json small_visual_json() {
  auto j = nlohmann::ordered_json::parse(read_text_file(test::fixture_calibration("LKG-APW92011.visual.json")));
  j["screenW"]["value"] = 384;
  j["screenH"]["value"] = 216;
  j["DPI"]["value"] = 28.3;
  j["pitch"]["value"] = 5.00693473815918;
  return j;
}

fs::path write_visual_json(const fs::path& dir) {
  const fs::path path = dir / "small.visual.json";
  std::ofstream(path) << small_visual_json().dump(1);
  return path;
}

// What `lfd calibrate` writes: the measured cone (36.5 deg, nominal 40), a correction field
// and a recommended view count.
fs::path write_calibration_json(const fs::path& dir) {
  nlohmann::ordered_json j;
  j["format"] = "lfd-calibration";
  j["version"] = 1;
  j["display"] = small_visual_json();
  j["display"]["viewCone"]["value"] = 36.5;
  std::vector<double> coefficients(16);
  for (size_t i = 0; i < coefficients.size(); ++i) coefficients[i] = 0.02 * double(int(i % 5) - 2);
  j["correction"] = {{"nx", 4}, {"ny", 4}, {"coefficients", coefficients}};
  j["view_cone_measured_deg"] = 36.5;
  j["view_cone_nominal_deg"] = 40.0;
  j["recommended_views"] = 45;
  const fs::path path = dir / "small.calibration.json";
  std::ofstream(path) << j.dump(1);
  return path;
}

// The quilt `lfd render --out DIR/<stem>.png` wrote: the one file whose name starts with
// <stem>_qs<cols>x<rows>a.
fs::path written_quilt(const fs::path& dir, const std::string& stem, int cols, int rows) {
  const std::string prefix = stem + "_qs" + std::to_string(cols) + "x" + std::to_string(rows) + "a";
  fs::path found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(prefix, 0) == 0) {
      EXPECT_TRUE(found.empty()) << "two quilts named " << prefix << "*";
      found = e.path();
    }
  EXPECT_FALSE(found.empty()) << "no quilt " << prefix << "* in " << dir;
  return found;
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RenderForADisplay, APlainVisualJsonGetsTheRulesViewsAndItsNominalCone) {
  const fs::path dir = test::temp_dir("render_display_visual");
  const fs::path visual = write_visual_json(dir);
  const display::DisplayQuilt expected = display::quilt_for_display(display::read_calibration(visual));
  EXPECT_EQ(expected.views_source, "view-count rule");
  const auto r = test::run_lfd("render --scene " + kScene + " --calibration " + visual.string() +
                               kRenderSmall + "--out " + (dir / "q.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // It says what it chose, in the library's words.
  EXPECT_NE(r.output.find(expected.describe()), std::string::npos)
      << "expected: " << expected.describe() << "\noutput: " << r.output;
  EXPECT_NE(r.output.find("(nominal)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("view cone 40.0 deg"), std::string::npos) << r.output;
  const fs::path quilt = written_quilt(dir, "q", expected.grid.cols, expected.grid.rows);
  const Image8 image = read_image(quilt.string(), 3);
  EXPECT_EQ(image.width, 48 * expected.grid.cols);
  EXPECT_EQ(image.height, 27 * expected.grid.rows);
}

TEST(RenderForADisplay, ACalibrationJsonGetsItsRecommendedViewsAndMeasuredCone) {
  const fs::path dir = test::temp_dir("render_display_calibration");
  const fs::path calibration = write_calibration_json(dir);
  const auto r = test::run_lfd("render --scene " + kScene + " --calibration " +
                               calibration.string() + kRenderSmall + "--out " +
                               (dir / "q.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("45 views (recommended by the calibration) in 5x9 tiles"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("view cone 36.50 deg (measured)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("view cone 36.5 deg"), std::string::npos) << r.output;
  const fs::path quilt = written_quilt(dir, "q", 5, 9);
  const Image8 image = read_image(quilt.string(), 3);
  EXPECT_EQ(image.width, 48 * 5);
  EXPECT_EQ(image.height, 27 * 9);
}

TEST(RenderForADisplay, ViewsOverrideTheRecommendation) {
  const fs::path dir = test::temp_dir("render_display_views");
  const fs::path calibration = write_calibration_json(dir);
  const auto r = test::run_lfd("render --scene " + kScene + " --calibration " +
                               calibration.string() + " --views 24" + kRenderSmall + "--out " +
                               (dir / "q.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const display::QuiltGrid grid = display::quilt_grid_for_views(24, 384.0 / 216.0);
  EXPECT_NE(r.output.find("24 views (--views) in " + std::to_string(grid.cols) + "x" +
                          std::to_string(grid.rows) + " tiles"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("(measured)"), std::string::npos) << r.output;
  written_quilt(dir, "q", grid.cols, grid.rows);
}

// --panel interlaces the quilt exactly as `lfd interlace` interlaces the written file.
void expect_panel_equals_interlace(const fs::path& calibration, const fs::path& dir,
                                   const std::string& extra, const std::string& size = "48x27") {
  const fs::path panel = dir / "panel.png", again = dir / "panel_interlace.png";
  const auto r = test::run_lfd("render --scene " + kScene + " --calibration " +
                               calibration.string() + " --chunks 8 --size " + size + extra +
                               " --panel " + panel.string() + " --out " + (dir / "q.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_TRUE(fs::exists(panel)) << r.output;
  const display::DisplayQuilt chosen = display::quilt_for_display(display::read_calibration(calibration));
  const fs::path quilt = written_quilt(dir, "q", chosen.grid.cols, chosen.grid.rows);
  const auto i = test::run_lfd("interlace --calibration " + calibration.string() + " --quilt " +
                               quilt.string() + extra + " --out " + again.string());
  ASSERT_EQ(i.exit_code, 0) << i.output;
  const Image8 a = read_image(panel.string(), 3), b = read_image(again.string(), 3);
  EXPECT_EQ(a.width, 384);
  EXPECT_EQ(a.height, 216);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  long differ = 0;
  for (size_t k = 0; k < a.pixels.size(); ++k) differ += a.pixels[k] != b.pixels[k];
  EXPECT_EQ(differ, 0) << "--panel and lfd interlace differ in " << differ << " of "
                       << a.pixels.size() << " subpixels";
  EXPECT_TRUE(bytes_of(panel) == bytes_of(again)) << "the PNG files differ";
  const auto same = test::run_lfd("compare " + panel.string() + " " + again.string() + " --json");
  ASSERT_EQ(same.exit_code, 0) << same.output;
  EXPECT_TRUE(nlohmann::json::parse(same.output)["identical"].get<bool>()) << same.output;
  // And the panel shows something: the scene, not a black image.
  long lit = 0;
  for (uint8_t p : a.pixels) lit += p > 16;
  EXPECT_GT(lit, long(a.pixels.size() / 10));
}

TEST(RenderForADisplay, PanelEqualsInterlaceOfTheWrittenQuiltForAVisualJson) {
  const fs::path dir = test::temp_dir("render_display_panel_visual");
  expect_panel_equals_interlace(write_visual_json(dir), dir, "");
}

TEST(RenderForADisplay, PanelEqualsInterlaceOfTheWrittenQuiltForACalibrationJson) {
  const fs::path dir = test::temp_dir("render_display_panel_calibration");
  expect_panel_equals_interlace(write_calibration_json(dir), dir, "");
}

TEST(RenderForADisplay, PanelEqualsInterlaceWithLinearBlendAndOverscan) {
  const fs::path dir = test::temp_dir("render_display_panel_linear");
  expect_panel_equals_interlace(write_calibration_json(dir), dir, " --blend linear --overscan");
}

TEST(RenderForADisplay, PanelEqualsInterlaceForTilesOfAnotherAspect) {
  // 7:3 tiles on a 16:9 panel: black bars, and an aspect the quilt name rounds (2.3333).
  const fs::path dir = test::temp_dir("render_display_panel_aspect");
  expect_panel_equals_interlace(write_calibration_json(dir), dir, "", "56x24");
}

// The 16" landscape Gen3 unit (data/displays/) at a tenth of its pixels, DPI and lens pitch.
fs::path write_small_gen3(const fs::path& dir) {
  auto j = nlohmann::ordered_json::parse(
      read_text_file(test::project_data() / "displays" / "16in-landscape-gen3.visual.json"));
  j["screenW"]["value"] = 384;
  j["screenH"]["value"] = 216;
  j["DPI"]["value"] = 28.3;
  j["pitch"]["value"] = 4.472;
  const fs::path path = dir / "gen3.visual.json";
  std::ofstream(path) << j.dump(1);
  return path;
}

TEST(RenderForADisplay, AGen3QuiltNamesThePanelAspectAndInterlacesWithNoBlackColumn) {
  // 30 rows at 16:9 round to 53 columns (aspect 1.7667): the quilt still names the panel's
  // 1.7778, and `lfd interlace` of it fills the panel to its first and last column (taken as
  // 1.7667 it would be fitted 0.6 % narrower: a black column at each edge of the 384 columns).
  const fs::path dir = test::temp_dir("render_display_gen3_aspect");
  const fs::path gen3 = write_small_gen3(dir);
  const auto r = test::run_lfd("render --scene " + kScene + " --calibration " + gen3.string() +
                               " --views 8 --size 53x30 --chunks 8 --background 1,1,1 --out " +
                               (dir / "q.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const display::QuiltGrid grid = display::quilt_grid_for_views(8, 384.0 / 216.0);
  const fs::path quilt = written_quilt(dir, "q", grid.cols, grid.rows);
  EXPECT_NE(quilt.filename().string().find("a1.7778."), std::string::npos) << quilt;
  const fs::path panel = dir / "panel.png";
  const auto i = test::run_lfd("interlace --calibration " + gen3.string() + " --quilt " + quilt.string() +
                               " --out " + panel.string());
  ASSERT_EQ(i.exit_code, 0) << i.output;
  const Image8 p = read_image(panel.string(), 3);
  ASSERT_EQ(p.width, 384);
  for (int x : {0, p.width - 1}) {
    int black = 0;
    for (int y = 0; y < p.height; ++y)
      black += p.pixels[(size_t(y) * p.width + x) * 3] == 0 && p.pixels[(size_t(y) * p.width + x) * 3 + 1] == 0 &&
               p.pixels[(size_t(y) * p.width + x) * 3 + 2] == 0;
    EXPECT_EQ(black, 0) << "column " << x << " has " << black << " black pixels";
  }
}

TEST(RenderForADisplay, PanelNeedsADisplayAndAWholeQuilt) {
  const fs::path dir = test::temp_dir("render_display_bad");
  auto r = test::run_lfd("render --scene " + kScene + kRenderSmall + "--panel " +
                         (dir / "p.png").string() + " --out " + (dir / "q.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--calibration"), std::string::npos) << r.output;
  r = test::run_lfd("render --scene " + kScene + " --calibration " + write_visual_json(dir).string() +
                    kRenderSmall + "--view 3 --panel " + (dir / "p.png").string() + " --out " +
                    (dir / "v.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--panel"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "p.png"));
}

}  // namespace
}  // namespace lfd
