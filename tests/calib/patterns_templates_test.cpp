// The factory templates shipped in data/displays (LKG-Toolkit HardCodedLKGDeviceTemplates.cs)
// are valid displays from which patterns can be planned.
#include <gtest/gtest.h>

#include "sim/patterns.hpp"
#include "display/visual_json.hpp"

namespace lfd::calib {
namespace {

std::filesystem::path templates() { return std::filesystem::path(LFD_SOURCE_DIR) / "data" / "displays"; }

TEST(PatternsTemplates, EveryShippedTemplateParsesAndPlansPatterns) {
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(templates())) {
    if (e.path().string().find(".visual.json") == std::string::npos) continue;
    const display::DisplayCalibration d = display::read_visual_json(e.path());
    EXPECT_NO_THROW(d.check(e.path().string()));
    display::Calibration c;
    c.display = d;
    const sim::PatternSet set = sim::plan_patterns(c);
    EXPECT_GE(set.board.corners_px.size(), 10u) << e.path();
    ++count;
  }
  EXPECT_EQ(count, 10);
}

TEST(PatternsTemplates, Gen3TemplatesCarryTheirSubpixelCells) {
  const display::DisplayCalibration p = display::read_visual_json(templates() / "16in-portrait-gen3.visual.json");
  EXPECT_EQ(p.cell_pattern_mode, 4);
  ASSERT_EQ(p.subpixel_cells.size(), 2u);
  EXPECT_DOUBLE_EQ(p.subpixel_cells[0].r_y, -0.31);
  const display::DisplayCalibration l = display::read_visual_json(templates() / "16in-landscape-gen3.visual.json");
  EXPECT_EQ(l.cell_pattern_mode, 2);
  EXPECT_DOUBLE_EQ(l.slope, -6.9);
  EXPECT_DOUBLE_EQ(display::read_visual_json(templates() / "go.visual.json").view_cone_deg, 54);
}

}  // namespace
}  // namespace lfd::calib
