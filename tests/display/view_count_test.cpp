#include "calib/display/view_count.hpp"

#include <gtest/gtest.h>

#include "calib/display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

Calibration unit(const char* file) {
  Calibration c;
  c.display = read_visual_json(test::shared_data() / "calibrations" / file);
  return c;
}

TEST(ViewCount, RealUnitsGetTheCountsTheSimulatorSweepSupports) {
  LFD_REQUIRE_SHARED_DATA();
  // docs/display-model.md: parallax blur within ~10 % of its floor at these counts.
  EXPECT_EQ(recommend_view_count(unit("LKG-2K-04409.visual.json")).views, 40);
  EXPECT_EQ(recommend_view_count(unit("LKG-APW92011.visual.json")).views, 32);
  const auto a = recommend_view_count(unit("LKG-APW92011.visual.json"));
  EXPECT_EQ(a.cols * a.rows, a.views);
  EXPECT_NE(a.rule.find("sigma_eff"), std::string::npos);
}

TEST(ViewCount, AWiderLensBlurMeansFewerViews) {
  LFD_REQUIRE_SHARED_DATA();
  Calibration c = unit("LKG-APW92011.visual.json");
  c.phase_blur_sigma = 0.02;
  EXPECT_LT(recommend_view_count(c).views, 32);
}

TEST(ViewCount, PhaseUncertaintyLimitsTheCountButSampleNoiseDoesNot) {
  LFD_REQUIRE_SHARED_DATA();
  Calibration c = unit("LKG-APW92011.visual.json");
  c.residuals = ResidualStats{0.05, 0.02, 0.99, 100000};  // noise of single phase samples
  EXPECT_EQ(recommend_view_count(c).views, 32);
  c.uncertainty["center_periods"] = 0.008;
  c.uncertainty["correction_rms_periods"] = 0.006;  // combined 0.01: a view >= 0.04 wide
  const auto a = recommend_view_count(c);
  EXPECT_NEAR(a.accuracy_limit, 25.0, 1e-9);
  EXPECT_EQ(a.views, 24);
}

}  // namespace
}  // namespace lfd::calib
