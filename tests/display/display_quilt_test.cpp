// The quilt for a display (display/display_quilt.hpp): the tile grid for a view count,
// and what a calibration decides (views, grid, aspect, cone).
#include "display/display_quilt.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "display/view_count.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::display {
namespace {

struct GridCase {
  int views;
  double aspect;
  int cols, rows;
};

TEST(QuiltGridForViews, MatchesTheLookingGlassLayouts) {
  for (const GridCase& c : {GridCase{45, 16.0 / 9.0, 5, 9},   // landscape Gen2
                            GridCase{48, 0.75, 8, 6},          // Portrait
                            GridCase{1, 16.0 / 9.0, 1, 1},
                            GridCase{1, 0.75, 1, 1},
                            GridCase{32, 16.0 / 9.0, 4, 8},
                            GridCase{100, 1.0, 10, 10}}) {
    const QuiltGrid g = quilt_grid_for_views(c.views, c.aspect);
    EXPECT_EQ(g.cols, c.cols) << c.views << " views at aspect " << c.aspect;
    EXPECT_EQ(g.rows, c.rows) << c.views << " views at aspect " << c.aspect;
  }
}

TEST(QuiltGridForViews, APrimeCountFillsOneRowOrColumnWithoutEmptyTiles) {
  for (int views : {2, 7, 13, 41, 251})
    for (double aspect : {16.0 / 9.0, 0.75}) {
      const QuiltGrid g = quilt_grid_for_views(views, aspect);
      EXPECT_EQ(g.cols * g.rows, views) << views;
      EXPECT_TRUE(g.cols == 1 || g.rows == 1) << views << ": " << g.cols << "x" << g.rows;
    }
}

TEST(QuiltGridForViews, NeverLeavesEmptyTilesAndPicksTheSquarestTexture) {
  for (double aspect : {16.0 / 9.0, 0.75, 1.0, 2.5})
    for (int views = 1; views <= 256; ++views) {
      const QuiltGrid g = quilt_grid_for_views(views, aspect);
      ASSERT_EQ(g.cols * g.rows, views) << views << " at " << aspect;
      // Among the exact factorisations, none gives a texture closer to square.
      const double chosen = std::abs(std::log(g.cols * aspect / g.rows));
      for (int cols = 1; cols <= views; ++cols) {
        if (views % cols != 0) continue;
        EXPECT_GE(std::abs(std::log(cols * aspect / (views / cols))), chosen - 1e-12)
            << views << " at " << aspect << ": " << cols << " columns beat " << g.cols;
      }
    }
}

TEST(QuiltGridForViews, RejectsImpossibleInput) {
  EXPECT_THROW(quilt_grid_for_views(0, 1.0), InputError);
  EXPECT_THROW(quilt_grid_for_views(-5, 1.0), InputError);
  EXPECT_THROW(quilt_grid_for_views(257, 1.0), InputError);
  EXPECT_THROW(quilt_grid_for_views(45, 0.0), InputError);
  EXPECT_THROW(quilt_grid_for_views(45, -1.0), InputError);
  EXPECT_THROW(quilt_grid_for_views(45, std::numeric_limits<double>::quiet_NaN()), InputError);
  EXPECT_THROW(quilt_grid_for_views(45, std::numeric_limits<double>::infinity()), InputError);
}

Calibration unit(const char* file) {
  Calibration c;
  c.display = read_visual_json(test::fixture_calibration(file));
  return c;
}

TEST(QuiltForDisplay, ViewsFromTheUserOverrideEverything) {
  Calibration c = unit("LKG-APW92011.visual.json");
  c.recommended_views = 32;
  const DisplayQuilt q = quilt_for_display(c, 48);
  EXPECT_EQ(q.views, 48);
  EXPECT_EQ(q.views_source, "--views");
  const QuiltGrid g = quilt_grid_for_views(48, 16.0 / 9.0);
  EXPECT_EQ(q.grid.cols, g.cols);
  EXPECT_EQ(q.grid.rows, g.rows);
}

TEST(QuiltForDisplay, ViewsFromTheCalibrationsRecommendation) {
  Calibration c = unit("LKG-APW92011.visual.json");
  c.recommended_views = 45;
  const DisplayQuilt q = quilt_for_display(c);
  EXPECT_EQ(q.views, 45);
  EXPECT_EQ(q.views_source, "recommended by the calibration");
  EXPECT_EQ(q.grid.cols, 5);
  EXPECT_EQ(q.grid.rows, 9);
}

TEST(QuiltForDisplay, ViewsFromTheRuleWithoutARecommendation) {
  for (const char* file : {"LKG-APW92011.visual.json", "LKG-PORT-portrait.visual.json"}) {
    const Calibration c = unit(file);
    const DisplayQuilt q = quilt_for_display(c);
    const ViewCountAdvice advice = recommend_view_count(c);
    EXPECT_EQ(q.views, advice.views) << file;
    EXPECT_EQ(q.views_source, "view-count rule") << file;
    EXPECT_EQ(q.grid.cols * q.grid.rows, q.views) << file;
    EXPECT_EQ(q.grid.cols, advice.cols) << file;
    EXPECT_EQ(q.grid.rows, advice.rows) << file;
  }
}

TEST(QuiltForDisplay, TilesHaveThePanelsAspect) {
  const DisplayQuilt landscape = quilt_for_display(unit("LKG-APW92011.visual.json"));
  EXPECT_DOUBLE_EQ(landscape.view_aspect, 3840.0 / 2160.0);
  const DisplayQuilt portrait = quilt_for_display(unit("LKG-PORT-portrait.visual.json"));
  EXPECT_DOUBLE_EQ(portrait.view_aspect, 1536.0 / 2048.0);
  const ViewSize s = view_size_for_display(landscape, 270);
  EXPECT_EQ(s.height, 270);
  EXPECT_EQ(s.width, 480);
  EXPECT_EQ(view_size_for_display(portrait).width, 384);
  EXPECT_EQ(view_size_for_display(portrait).height, 512);
}

TEST(QuiltForDisplay, TheConeIsTheMeasuredOneWhenThereIsOne) {
  Calibration c = unit("LKG-APW92011.visual.json");
  DisplayQuilt q = quilt_for_display(c);
  EXPECT_EQ(q.view_cone_deg, 40.0);
  EXPECT_FALSE(q.cone_measured);
  EXPECT_NE(q.describe().find("nominal"), std::string::npos) << q.describe();

  c.view_cone_nominal_deg = 40.0;
  c.view_cone_measured_deg = 36.5;
  c.display.view_cone_deg = 36.5;
  q = quilt_for_display(c);
  EXPECT_EQ(q.view_cone_deg, 36.5);
  EXPECT_TRUE(q.cone_measured);
  EXPECT_EQ(effective_view_cone_deg(c), 36.5);
  EXPECT_NE(q.describe().find("measured"), std::string::npos) << q.describe();
}

TEST(QuiltForDisplay, DescribesWhatItChose) {
  Calibration c = unit("LKG-APW92011.visual.json");
  c.recommended_views = 45;
  const std::string text = quilt_for_display(c).describe();
  for (const char* part : {"45 views", "recommended by the calibration", "5x9", "40.00 deg"})
    EXPECT_NE(text.find(part), std::string::npos) << part << " not in: " << text;
}

TEST(QuiltForDisplay, RejectsAnImpossibleViewCount) {
  const Calibration c = unit("LKG-APW92011.visual.json");
  EXPECT_THROW(quilt_for_display(c, 0), InputError);
  EXPECT_THROW(quilt_for_display(c, 1000), InputError);
}

}  // namespace
}  // namespace lfd::display
