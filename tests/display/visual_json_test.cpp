#include "display/visual_json.hpp"

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::display {
namespace {

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

TEST(VisualJson, EveryRealCalibrationRoundTripsByteForByte) {
  const auto files = test::fixture_calibrations();
  ASSERT_GE(files.size(), 4u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const std::string text = read_text_file(file);
    const DisplayCalibration c = read_visual_json(file);
    EXPECT_EQ(to_visual_json(c).dump(), trim(text));
    const auto dir = test::temp_dir("visual_roundtrip");
    write_visual_json(dir / "out.json", c);
    const DisplayCalibration again = read_visual_json(dir / "out.json");
    EXPECT_EQ(again.pitch_lpi, c.pitch_lpi);
    EXPECT_EQ(again.slope, c.slope);
    EXPECT_EQ(again.center_periods, c.center_periods);
    EXPECT_EQ(again.subpixel_cells.size(), c.subpixel_cells.size());
  }
}

TEST(VisualJson, ReadsTheValuesOfA16InchGen2Unit) {
  const auto c = read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json"));
  EXPECT_EQ(c.serial, "LKG-APW92011");
  EXPECT_DOUBLE_EQ(c.pitch_lpi, 50.0693473815918);
  EXPECT_DOUBLE_EQ(c.slope, -7.521984100341797);
  EXPECT_DOUBLE_EQ(c.center_periods, 0.07635253667831421);
  EXPECT_EQ(c.screen_w, 3840);
  EXPECT_EQ(c.screen_h, 2160);
  EXPECT_TRUE(c.inv_view);
  EXPECT_FALSE(c.has_cells());
}

TEST(VisualJson, ReadsGen3CellsAndPatternMode) {
  const auto c = read_visual_json(test::fixture_calibration("template-16in-portrait-gen3.visual.json"));
  EXPECT_EQ(c.cell_pattern_mode, 4);
  ASSERT_EQ(c.subpixel_cells.size(), 2u);
  EXPECT_DOUBLE_EQ(c.subpixel_cells[0].r_x, -0.25);
  EXPECT_DOUBLE_EQ(c.subpixel_cells[0].g_y, 0.28);
  EXPECT_DOUBLE_EQ(c.subpixel_cells[1].b_x, -0.25);
}

constexpr const char* kMinimal =
    R"({"configVersion":"3.0","serial":"X","pitch":{"value":50},"slope":{"value":-7},)"
    R"("center":{"value":0.5},"viewCone":{"value":40},"invView":{"value":1},"DPI":{"value":283},)"
    R"("screenW":{"value":3840},"screenH":{"value":2160},"myVendorField":{"value":42},"notes":"kept"})";

TEST(VisualJson, KeepsUnknownFieldsAndWritesChangesWrapped) {
  DisplayCalibration c = parse_visual_json(kMinimal, "mem.json");
  c.pitch_lpi = 50.25;
  const auto j = to_visual_json(c);
  EXPECT_EQ(j["myVendorField"]["value"], 42);
  EXPECT_EQ(j["notes"], "kept");
  EXPECT_EQ(j["pitch"]["value"], 50.25);
  EXPECT_EQ(j["slope"]["value"], -7);  // unchanged values keep their stored form
}

TEST(VisualJson, AcceptsUnwrappedNumbersAndLowerCaseCellPatternMode) {
  const auto c = parse_visual_json(
      R"({"pitch":49.5,"slope":5.5,"center":0.1,"DPI":338,"screenW":2560,"screenH":1600,"cellPatternMode":{"value":2}})",
      "plain.json");
  EXPECT_DOUBLE_EQ(c.pitch_lpi, 49.5);
  EXPECT_EQ(c.cell_pattern_mode, 2);
}

// Each bad value: exit-2 error naming the file and the field.
struct BadCase {
  const char* name;
  std::string from, to;
  const char* field;
};

class VisualJsonBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(VisualJsonBadInput, IsRejectedNamingFileAndField) {
  const BadCase& b = GetParam();
  std::string text = kMinimal;
  const auto pos = text.find(b.from);
  ASSERT_NE(pos, std::string::npos) << b.from;
  text.replace(pos, b.from.size(), b.to);
  try {
    parse_visual_json(text, "unit.visual.json");
    FAIL() << "accepted " << text;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("unit.visual.json"), std::string::npos) << msg;
    EXPECT_NE(msg.find(b.field), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Fields, VisualJsonBadInput,
    ::testing::Values(
        BadCase{"ZeroPitch", R"("pitch":{"value":50})", R"("pitch":{"value":0})", "pitch"},
        BadCase{"NegativePitch", R"("pitch":{"value":50})", R"("pitch":{"value":-3})", "pitch"},
        BadCase{"ZeroSlope", R"("slope":{"value":-7})", R"("slope":{"value":0})", "slope"},
        BadCase{"NaNSlope", R"("slope":{"value":-7})", R"("slope":{"value":"NaN"})", "slope"},
        BadCase{"InfiniteCenter", R"("center":{"value":0.5})", R"("center":{"value":1e999})",
                "1e999"},  // JSON overflow: rejected by the parser, naming the value
        BadCase{"ZeroDPI", R"("DPI":{"value":283})", R"("DPI":{"value":0})", "DPI"},
        BadCase{"NegativeWidth", R"("screenW":{"value":3840})", R"("screenW":{"value":-1})",
                "screenW"},
        BadCase{"FractionalHeight", R"("screenH":{"value":2160})", R"("screenH":{"value":2160.5})",
                "screenH"},
        BadCase{"MissingPitch", R"("pitch":{"value":50},)", "", "pitch"},
        BadCase{"CellPatternModeOutOfRange", R"("notes":"kept")",
                R"("CellPatternMode":{"value":5})", "CellPatternMode"},
        BadCase{"ElevenCells", R"("notes":"kept")",
                std::string(R"("subpixelCells":[)") + [] {
                  std::string cells;
                  for (int i = 0; i < 11; ++i)
                    cells += std::string(i ? "," : "") +
                             R"({"ROffsetX":0,"ROffsetY":0,"GOffsetX":0,"GOffsetY":0,"BOffsetX":0,"BOffsetY":0})";
                  return cells;
                }() + "]",
                "subpixelCells"},
        BadCase{"CellMissingOffset", R"("notes":"kept")",
                R"("subpixelCells":[{"ROffsetX":0,"ROffsetY":0,"GOffsetX":0,"GOffsetY":0,"BOffsetX":0}])",
                "BOffsetY"},
        BadCase{"ViewConeZero", R"("viewCone":{"value":40})", R"("viewCone":{"value":0})",
                "viewCone"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(VisualJson, NotJsonNamesTheFile) {
  try {
    parse_visual_json("{\"pitch\": ", "broken.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace lfd::display
