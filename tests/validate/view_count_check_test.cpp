#include "validate/view_count_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "display/view_count.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::validate {
namespace {

// Profiles in which every direction sees exactly one view: the one whose bin holds it.
ViewProfiles ideal_profiles(int views, double cone_deg, int angles) {
  ViewProfiles p;
  p.views = views;
  p.view.assign(views, std::vector<double>(angles, 0.0));
  p.black.assign(angles, 0.0);
  const double t = std::tan(0.5 * cone_deg * std::numbers::pi / 180.0);
  for (int a = 0; a < angles; ++a) {
    const double s = -0.5 + (a + 0.5) / angles;  // camera offset of this direction
    p.theta_deg.push_back(std::atan(2.0 * s * t) * 180.0 / std::numbers::pi);
    const int j = std::min(views - 1, int(std::floor((s + 0.5) * views)));
    p.view[j][a] = 1.0;
  }
  return p;
}

TEST(ParallaxBlur, PerfectViewsLeaveOnlyTheQuantisationOfTheViewpoint) {
  // Uniform positions inside a bin of width 1/V around its centre: RMS = 1/(V sqrt(12)),
  // mean absolute = 1/(4V); the mean over directions of |s_j - s| is the latter.
  for (int views : {8, 24, 45}) {
    const ViewProfiles p = ideal_profiles(views, 40.0, views * 200);
    EXPECT_NEAR(parallax_blur(p, 40.0), 1.0 / (4.0 * views), 0.02 / views) << views;
  }
}

TEST(ParallaxBlur, CrosstalkFromANeighbourWidensIt) {
  ViewProfiles p = ideal_profiles(16, 40.0, 3200);
  const double clean = parallax_blur(p, 40.0);
  for (size_t a = 0; a < p.theta_deg.size(); ++a)
    for (int j = 0; j + 1 < p.views; ++j)
      if (p.view[j][a] > 0.5) p.view[j + 1][a] = 0.3;  // ghost of the next view
  EXPECT_GT(parallax_blur(p, 40.0), 1.5 * clean);
}

TEST(ParallaxBlur, BlackLevelIsSubtracted) {
  ViewProfiles p = ideal_profiles(16, 40.0, 1600);
  const double clean = parallax_blur(p, 40.0);
  for (auto& v : p.view)
    for (double& x : v) x += 0.2;
  for (double& k : p.black) k = 0.2;
  EXPECT_NEAR(parallax_blur(p, 40.0), clean, 1e-12);
}

// The view-count rule picks the knee of the parallax blur, measured through the simulator: at
// the recommended count more views no longer lower the blur by more than ~10 % (it is near its
// floor, the blur at many views), and fewer views raise it.
class ViewCountKnee : public ::testing::TestWithParam<const char*> {};

TEST_P(ViewCountKnee, TheRecommendedCountSitsAtTheKnee) {
  display::Calibration truth;
  truth.display = display::read_visual_json(test::fixture_calibration(GetParam()));
  const int recommended = display::recommend_view_count(truth).views;
  const std::vector<int> counts = {16, 24, 32, 40, 48, 64, 96};
  ASSERT_NE(std::find(counts.begin(), counts.end(), recommended), counts.end()) << recommended;
  ASSERT_GT(recommended, counts.front());
  ProfileOptions options;
  options.panel_points = 250;
  const ViewCountSweep sweep = sweep_view_counts(truth, counts, options);
  ASSERT_EQ(sweep.recommended, recommended);
  auto blur_at = [&](int views) {
    for (const auto& p : sweep.points)
      if (p.views == views) return p.parallax_blur;
    ADD_FAILURE() << "no point for " << views << " views";
    return 0.0;
  };
  const auto at = std::find(counts.begin(), counts.end(), recommended);
  const double blur = blur_at(recommended), fewer = blur_at(*(at - 1)), floor = sweep.blur_floor;
  for (const auto& p : sweep.points)
    std::printf("%s: %d views, blur %.5f (%.3f x floor)\n", GetParam(), p.views, p.parallax_blur,
                p.parallax_blur / floor);
  // The sweep has a knee at all: few views blur far more than many.
  EXPECT_GT(blur_at(16), 1.25 * floor);
  // Beyond the recommended count, at most ~10 % more to gain.
  EXPECT_LT(blur, 1.12 * floor);
  // Below it, the blur rises.
  EXPECT_GT(fewer, 1.03 * blur) << *(at - 1) << " views";
  // And the sweep's own saturation point (within 10 % of the floor) is the recommendation or
  // the next count.
  EXPECT_GE(sweep.saturation, recommended);
  EXPECT_LE(sweep.saturation, *(at + 1));
}

INSTANTIATE_TEST_SUITE_P(RealUnits, ViewCountKnee,
                         ::testing::Values("LKG-2K-04409.visual.json", "LKG-PORT-portrait.visual.json"),
                         [](const auto& info) {
                           std::string name = info.param;
                           name = name.substr(0, name.find('.'));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace lfd::validate
