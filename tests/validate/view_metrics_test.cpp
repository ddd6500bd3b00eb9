// Crosstalk and view separation definitions (docs/validation.md "View separation").
#include <gtest/gtest.h>

#include "validate/view_metrics.hpp"

namespace lfd::validate {
namespace {

// Three views, three directions; view i peaks at direction i.
ViewProfiles three_views() {
  ViewProfiles p;
  p.views = 3;
  p.theta_deg = {-10, 0, 10};
  p.view = {{0.80, 0.10, 0.05}, {0.20, 0.70, 0.15}, {0.05, 0.10, 0.60}};
  p.black = {0.02, 0.02, 0.02};
  return p;
}

TEST(ViewMetrics, CrosstalkAndSeparationAtEachViewsPeak) {
  const ViewSummary s = summarise(three_views());
  ASSERT_EQ(s.per_view.size(), 3u);
  // View 0 peaks at -10 deg: L - L_K = 0.78, 0.18, 0.03.
  EXPECT_DOUBLE_EQ(s.per_view[0].peak_theta_deg, -10);
  EXPECT_NEAR(s.per_view[0].peak_luminance, 0.78, 1e-12);
  EXPECT_NEAR(s.per_view[0].crosstalk, (0.18 + 0.03) / 0.78, 1e-12);
  EXPECT_NEAR(s.per_view[0].separation, 0.78 / (0.78 + 0.18 + 0.03), 1e-12);
  // With three views both others are neighbours (the cone wraps).
  EXPECT_NEAR(s.per_view[0].adjacent_crosstalk, s.per_view[0].crosstalk, 1e-12);
  EXPECT_NEAR(s.per_view[2].separation, 0.58 / (0.03 + 0.13 + 0.58), 1e-12);
  EXPECT_NEAR(s.mean_separation,
              (s.per_view[0].separation + s.per_view[1].separation + s.per_view[2].separation) / 3,
              1e-12);
}

TEST(ViewMetrics, PureViewsHaveNoCrosstalk) {
  ViewProfiles p = three_views();
  p.view = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  p.black = {0, 0, 0};
  const ViewSummary s = summarise(p);
  EXPECT_DOUBLE_EQ(s.mean_separation, 1.0);
  EXPECT_DOUBLE_EQ(s.mean_crosstalk, 0.0);
}

}  // namespace
}  // namespace lfd::validate
