#include "validate/view_count_check.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lfd::validate
