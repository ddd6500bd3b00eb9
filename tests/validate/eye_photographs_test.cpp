// Photographs from eyes between quilt views (validate/eye_photographs.hpp) on a display whose
// views are flat colours, so what each eye must see is known: the nearest-view panel shows the
// eye view j's colour until halfway to j + 1 and view j + 1's after, the linear one their mix.
#include "validate/eye_photographs.hpp"

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "interlace/interlacer.hpp"
#include "render/quilt_layout.hpp"
#include "tests/support/small_displays.hpp"
#include "util/error.hpp"

namespace lfd::validate {
namespace {

constexpr int kViews = 8, kW = 80, kH = 50;

std::array<float, 3> colour(double j) { return {float(j / (kViews - 1)), float(1 - j / (kViews - 1)), 0.5f}; }

ImageF flat(std::array<float, 3> c) {
  ImageF im(kW, kH, 3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int ch = 0; ch < 3; ++ch) im.at(x, y, ch) = c[size_t(ch)];
  return im;
}

ImageF quilt_panel(const display::LensModel& lens, interlace::ViewBlend blend) {
  render::QuiltLayout layout;
  layout.cols = 4;
  layout.rows = 2;
  layout.views = kViews;
  layout.width = 4 * kW;
  layout.height = 2 * kH;
  layout.aspect = double(kW) / kH;
  ImageF quilt(layout.width, layout.height, 3);
  for (int j = 0; j < kViews; ++j)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        for (int ch = 0; ch < 3; ++ch)
          quilt.at(layout.tile_x(j) + x, layout.tile_y_top_down(j) + y, ch) = colour(j)[size_t(ch)];
  interlace::InterlaceOptions o;
  o.blend = blend;
  return interlace::interlace(quilt, layout, lens, o);
}

struct Photos {
  const display::LensModel lens{test::small_lkg_2k()};
  const sim::DisplaySimulator simulator{lens};
  ImageF photo(const ImageF& panel, const EyeBetweenViews& eye) const { return photograph(simulator, panel, eye, 96, 0.002, 2); }
  // PSNR of the photograph of `panel` against the photograph of an ideal panel of flat colour c.
  double against(const ImageF& panel, const EyeBetweenViews& eye, std::array<float, 3> c) const {
    return photo_psnr(photo(panel, eye), photo(single_view_panel(lens, flat(c)), eye));
  }
};

TEST(EyePhotographs, NearestViewPanelShowsTheViewTheEyeIsNearest) {
  const Photos p;
  const ImageF nearest = quilt_panel(p.lens, interlace::ViewBlend::kNearest);
  for (int j : {1, 3, 5}) {
    const EyeBetweenViews on = eye_between_views(p.lens, kViews, j, 0.0);
    EXPECT_GT(p.against(nearest, on, colour(j)), 35.0) << "view " << j;
    EXPECT_LT(p.against(nearest, on, colour(j + 1)), 25.0) << "view " << j;
    EXPECT_LT(p.against(nearest, on, colour(kViews - 1 - j)), 25.0) << "mirrored view " << j;
    EXPECT_GT(p.against(nearest, eye_between_views(p.lens, kViews, j, 0.25), colour(j)), 35.0) << "view " << j;
    EXPECT_GT(p.against(nearest, eye_between_views(p.lens, kViews, j, 0.75), colour(j + 1)), 35.0) << "view " << j;
  }
}

TEST(EyePhotographs, LinearPanelShowsTheMixHalfwayBetweenViews) {
  const Photos p;
  const ImageF linear = quilt_panel(p.lens, interlace::ViewBlend::kLinear);
  const EyeBetweenViews half = eye_between_views(p.lens, kViews, 3, 0.5);
  EXPECT_GT(p.against(linear, half, colour(3.5)), 35.0);
  EXPECT_LT(p.against(linear, half, colour(3)), 30.0);
}

TEST(EyePhotographs, EyeStandsWhereTheDisplaySendsItsFraction) {
  const display::LensModel lens(test::small_lkg_2k());
  const EyeBetweenViews centre = eye_between_views(lens, kViews, 3, 0.5);
  EXPECT_DOUBLE_EQ(centre.fraction, 0.5);
  EXPECT_NEAR(centre.eye.x(), 0.0, 1e-12);
  const EyeBetweenViews right = eye_between_views(lens, kViews, 6, 0.5);
  EXPECT_DOUBLE_EQ(right.position_s, 7.0 / 8 - 0.5);
  EXPECT_GT(right.eye.z(), 100 * lens.calibration().width_m());
}

TEST(EyePhotographs, BadPositionsAreInputErrors) {
  const display::LensModel lens(test::small_lkg_2k());
  EXPECT_THROW(eye_between_views(lens, kViews, kViews, 0.0), InputError);
  EXPECT_THROW(eye_between_views(lens, kViews, 2, 1.5), InputError);
  EXPECT_THROW(eye_between_views(lens, kViews, kViews - 1, 0.5), InputError);
}

}  // namespace
}  // namespace lfd::validate
