// The view-count rule (display/view_count.hpp) as a rule: the count is the largest quilt
// count under every limit, and each limit moves it the way its physics says. Whether the rule
// picks the knee of the parallax blur is measured with the simulator in
// tests/validate/view_count_check_test.cpp.
#include "display/view_count.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "display/display_quilt.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::display {
namespace {

Calibration unit(const std::filesystem::path& file) {
  Calibration c;
  c.display = read_visual_json(file);
  return c;
}

TEST(ViewCount, StaysUnderEveryLimitAndFillsItsQuiltGrid) {
  for (const auto& file : test::fixture_calibrations()) {
    SCOPED_TRACE(file.string());
    const Calibration c = unit(file);
    const ViewCountAdvice a = recommend_view_count(c);
    EXPECT_GE(a.views, 16);
    EXPECT_LE(a.views, 100);
    const double limit = std::min({a.sampling_limit, a.blur_limit, a.accuracy_limit});
    if (limit >= 16) {
      EXPECT_LE(a.views, limit + 1e-9);
    }
    const QuiltGrid g = quilt_grid_for_views(a.views, double(c.display.screen_w) / c.display.screen_h);
    EXPECT_EQ(a.cols, g.cols);
    EXPECT_EQ(a.rows, g.rows);
    EXPECT_NE(a.rule.find("sigma_eff"), std::string::npos);
  }
}

TEST(ViewCount, TheBlurLimitIsOneViewPer1point6SigmaEff) {
  Calibration c = unit(test::fixture_calibration("LKG-APW92011.visual.json"));
  c.phase_blur_sigma = 0.01;
  const ViewCountAdvice a = recommend_view_count(c);
  const double w_sub = 1.0 / LensModel(c.display).subpixels_per_lens();
  const double sigma_eff = std::sqrt(0.01 * 0.01 + w_sub * w_sub / 12.0);
  EXPECT_NEAR(a.blur_limit, 1.0 / (kViewWidthInSigmas * sigma_eff), 1e-9);
}

TEST(ViewCount, AWiderLensBlurMeansFewerViews) {
  Calibration c = unit(test::fixture_calibration("LKG-APW92011.visual.json"));
  const int sharp = recommend_view_count(c).views;
  c.phase_blur_sigma = 0.02;
  EXPECT_LT(recommend_view_count(c).views, sharp);
}

TEST(ViewCount, PhaseUncertaintyLimitsTheCountButSampleNoiseDoesNot) {
  Calibration c = unit(test::fixture_calibration("LKG-APW92011.visual.json"));
  const int plain = recommend_view_count(c).views;
  c.residuals = ResidualStats{0.05, 0.02, 0.99, 100000};  // noise of single phase samples
  EXPECT_EQ(recommend_view_count(c).views, plain);
  c.uncertainty["center_periods"] = 0.008;
  c.uncertainty["correction_rms_periods"] = 0.006;  // combined 0.01: a view >= 0.04 wide
  const auto a = recommend_view_count(c);
  EXPECT_NEAR(a.accuracy_limit, 25.0, 1e-9);
  EXPECT_LE(a.views, 25);
  EXPECT_LT(a.views, plain);
}

}  // namespace
}  // namespace lfd::display
