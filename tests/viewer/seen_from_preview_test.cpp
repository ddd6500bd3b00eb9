// The "seen from" preview: a panel interlaced (CPU reference) from a quilt whose views are flat,
// distinct colours; from the direction of view j the preview shows view j, and an eye moving
// across the cone walks through the views in order.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "display/lens_relations.hpp"
#include "display/visual_json.hpp"
#include "interlace/interlacer.hpp"
#include "tests/support/small_displays.hpp"
#include "util/error.hpp"
#include "viewer/seen_from_preview.hpp"

namespace lfd::viewer {
namespace {

constexpr int kViews = 8;
// View k is a flat colour from red (view 0) to blue (view 7): the red share of the light seen,
// R / (R + B), tells which view (and which mix of neighbours) an eye sees, whatever the lenses
// do to the brightness.
std::array<float, 3> view_colour(int k) { return {float(kViews - 1 - k) / (kViews - 1), 0.0f, float(k) / (kViews - 1)}; }

ImageF flat_view_panel(const display::LensModel& lens) {
  render::QuiltLayout q;
  q.cols = 4;
  q.rows = 2;
  q.views = kViews;
  q.width = 160;
  q.height = 100;
  q.aspect = 1.6;
  ImageF quilt(q.width, q.height, 3, 0.0f);
  for (int k = 0; k < kViews; ++k)
    for (int y = 0; y < q.tile_height(); ++y)
      for (int x = 0; x < q.tile_width(); ++x)
        for (int ch = 0; ch < 3; ++ch) quilt.at(q.tile_x(k) + x, q.tile_y_top_down(k) + y, ch) = view_colour(k)[ch];
  return interlace::interlace(quilt, q, lens);
}

// The mean colour of the preview's central half: what an eye that resolves neither single
// lenses nor single rows sees there (one lens shows each channel fully or not at all).
std::array<double, 3> central_mean(const ImageF& preview) {
  std::array<double, 3> sum{0, 0, 0};
  int n = 0;
  for (int y = preview.height / 4; y < 3 * preview.height / 4; ++y)
    for (int x = preview.width / 4; x < 3 * preview.width / 4; ++x, ++n)
      for (int ch = 0; ch < 3; ++ch) sum[ch] += preview.at(x, y, ch);
  for (double& v : sum) v /= n;
  return sum;
}

// Which view the colour is, as a real number: k for view k's colour, between two views for a mix.
double seen_view(const std::array<double, 3>& rgb) { return (kViews - 1) * rgb[2] / (rgb[0] + rgb[2]); }

double angle_of_view_deg(int view, double cone_deg) {
  const double tan_theta = display::tan_of_seen_fraction((view + 0.5) / kViews, cone_deg);
  return std::atan(tan_theta) * 180.0 / std::numbers::pi;
}

SeenFromOptions small_preview() {
  SeenFromOptions o;
  o.height_px = 48;
  return o;
}

TEST(SeenFromPreview, HasThePanelsAspect) {
  const display::LensModel lens(test::small_lkg_2k());
  const ImageF preview = seen_from_preview(lens, flat_view_panel(lens), SeenFromEye{}, small_preview());
  EXPECT_EQ(preview.height, 48);
  EXPECT_EQ(preview.width, 77);  // 48 x 320 / 200
  EXPECT_EQ(preview.channels, 3);
}

TEST(SeenFromPreview, FromTheAngleOfViewJTheCentreShowsViewJ) {
  const display::LensModel lens(test::small_lkg_2k());
  const ImageF panel = flat_view_panel(lens);
  for (int j = 0; j < kViews; ++j) {
    SeenFromEye eye;
    eye.angle_deg = angle_of_view_deg(j, 40.0);
    const std::array<double, 3> mean = central_mean(seen_from_preview(lens, panel, eye, small_preview()));
    EXPECT_GT(mean[0] + mean[2], 0.5) << "view " << j << ": too little light";
    // Mostly view j: at most a quarter of a view's mix of its neighbours.
    EXPECT_NEAR(seen_view(mean), j, 0.25) << "seen from " << eye.angle_deg << " deg";
  }
}

TEST(SeenFromPreview, AnEyeMovingAcrossTheConeWalksThroughTheViewsInOrder) {
  const display::LensModel lens(test::small_lkg_2k());
  const ImageF panel = flat_view_panel(lens);
  std::vector<double> walked;
  // From view 0's centre to view 7's (+-17.7 deg): past them, toward the cone's edges (+-20),
  // the neighbouring lens's far views mix in (the jump zone).
  for (double angle = -17.5; angle <= 17.5; angle += 1.0) {
    SeenFromEye eye;
    eye.angle_deg = angle;
    walked.push_back(seen_view(central_mean(seen_from_preview(lens, panel, eye, small_preview()))));
  }
  for (size_t i = 1; i < walked.size(); ++i) EXPECT_GE(walked[i], walked[i - 1] - 0.1) << "step " << i;
  EXPECT_LT(walked.front(), 0.3);  // view 0 on the left
  EXPECT_GT(walked.back(), kViews - 1.3);  // view 7 on the right
}

TEST(SeenFromPreview, IsRecomputedOnlyWhenShownChangedAndNotTooOften) {
  EXPECT_TRUE(seen_from_refresh_due(true, false, -1));   // the first one
  EXPECT_FALSE(seen_from_refresh_due(false, true, 10));  // hidden: no read-back
  EXPECT_FALSE(seen_from_refresh_due(true, false, 10));  // nothing moved
  EXPECT_FALSE(seen_from_refresh_due(true, true, 0.5 * kSeenFromMinIntervalS));
  EXPECT_TRUE(seen_from_refresh_due(true, true, kSeenFromMinIntervalS));
}

TEST(SeenFromPreview, BadOptionsAndPanelsAreInputErrors) {
  const display::LensModel lens(test::small_lkg_2k());
  SeenFromOptions o;
  o.height_px = 0;
  EXPECT_THROW(seen_from_preview(lens, flat_view_panel(lens), SeenFromEye{}, o), InputError);
  EXPECT_THROW(seen_from_preview(lens, ImageF(10, 10, 3), SeenFromEye{}), InputError);
  SeenFromEye behind;
  behind.distance_m = 0;
  EXPECT_THROW(seen_from_preview(lens, flat_view_panel(lens), behind), InputError);
}

}  // namespace
}  // namespace lfd::viewer
