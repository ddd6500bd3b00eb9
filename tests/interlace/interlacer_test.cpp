#include "interlace/interlacer.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "interlace/quilt_file.hpp"
#include "tests/support/quilt_layouts.hpp"
#include "tests/support/small_displays.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::interlace {
namespace {

using display::DisplayCalibration;
using display::LensModel;
using render::QuiltLayout;

// A quilt whose tile k is filled with value(k) in every channel (top-down image).
ImageF constant_tile_quilt(const QuiltLayout& q, const std::function<float(int)>& value) {
  ImageF img(q.width, q.height, 3, 0.f);
  for (int k = 0; k < q.views; ++k)
    for (int y = 0; y < q.tile_height(); ++y)
      for (int x = 0; x < q.tile_width(); ++x)
        for (int c = 0; c < 3; ++c)
          img.at(q.tile_x(k) + x, q.tile_y_top_down(k) + y, c) = value(k);
  return img;
}

using test::quilt_layout;

TEST(Interlacer, EverySubpixelShowsTheViewTheVendorFormulaSelects) {
  const DisplayCalibration c = test::small_lkg_2k();
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(5, 9, 500, 900, 1.6);
  const ImageF quilt = constant_tile_quilt(q, [&](int k) { return (k + 0.5f) / q.views; });
  const ImageF panel = interlace(quilt, q, lens);
  ASSERT_EQ(panel.width, c.screen_w);
  ASSERT_EQ(panel.height, c.screen_h);
  const double P = lens.pitch_periods(), T = lens.tilt(), s = 1.0 / (3.0 * c.screen_w);
  for (int row = 0; row < c.screen_h; ++row)
    for (int x = 0; x < c.screen_w; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        const double u = (x + 0.5) / c.screen_w, v = 1.0 - (row + 0.5) / c.screen_h;
        const double a = (u + ch * s + v * T) * P - c.center_periods;
        const double f = std::clamp(1.0 - (a - std::floor(a)), 1e-5, 0.999999);
        const int expected = std::min(int(std::floor(f * q.views)), q.views - 1);
        const int got = int(std::lround(panel.at(x, row, ch) * q.views - 0.5));
        ASSERT_EQ(got, expected) << "x " << x << " row " << row << " channel " << ch;
      }
}

TEST(Interlacer, LinearBlendInterpolatesBetweenViewCentres) {
  const DisplayCalibration c = test::small_lkg_2k();
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(5, 9, 500, 900, 1.6);
  const ImageF quilt = constant_tile_quilt(q, [&](int k) { return float(k) / (q.views - 1); });
  InterlaceOptions o;
  o.blend = ViewBlend::kLinear;
  const ImageF panel = interlace(quilt, q, lens, o);
  for (int row = 0; row < c.screen_h; row += 7)
    for (int x = 0; x < c.screen_w; x += 3)
      for (int ch = 0; ch < 3; ++ch) {
        const double f = lens.subpixel_view_fraction(x, row, ch);
        const double t = std::clamp(f * q.views - 0.5, 0.0, double(q.views - 1));
        EXPECT_NEAR(panel.at(x, row, ch), t / (q.views - 1), 1e-5);
      }
}

TEST(Interlacer, ViewBlendNamesParseBackAndOthersAreRefused) {
  for (ViewBlend b : {ViewBlend::kNearest, ViewBlend::kLinear})
    EXPECT_EQ(parse_view_blend(view_blend_name(b)), b);
  EXPECT_THROW(parse_view_blend("bilinear"), InputError);
}

TEST(Interlacer, ViewZeroIsTheBottomLeftTile) {
  const DisplayCalibration c = test::small_lkg_2k();
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(4, 2, 80, 40, 1.0);
  ImageF quilt(80, 40, 3, 0.f);
  for (int y = 20; y < 40; ++y)  // bottom half of the image, left quarter
    for (int x = 0; x < 20; ++x) quilt.at(x, y, 1) = 1.f;
  const Interlacer il(lens, q);
  EXPECT_FLOAT_EQ(il.sample_tile(quilt, 0, 0.5, 0.5, 1), 1.f);
  EXPECT_FLOAT_EQ(il.sample_tile(quilt, 1, 0.5, 0.5, 1), 0.f);
  EXPECT_FLOAT_EQ(il.sample_tile(quilt, 4, 0.5, 0.5, 1), 0.f);  // top-left tile = view 4
}

TEST(Interlacer, SamplesNeverBleedIntoTheNeighbouringTile) {
  const DisplayCalibration c = test::small_lkg_2k();
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(2, 1, 20, 10, 1.0);
  ImageF quilt(20, 10, 3, 0.f);
  for (int y = 0; y < 10; ++y)
    for (int x = 10; x < 20; ++x) quilt.at(x, y, 0) = 1.f;
  const Interlacer il(lens, q);
  EXPECT_FLOAT_EQ(il.sample_tile(quilt, 0, 1.0, 0.5, 0), 0.f);
  EXPECT_FLOAT_EQ(il.sample_tile(quilt, 1, 0.0, 0.5, 0), 1.f);
}

TEST(Interlacer, SquareQuiltOnAWidePanelGetsBlackBarsUnlessOverscan) {
  const DisplayCalibration c = test::small_lkg_2k();  // 320x200, aspect 1.6
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(5, 9, 500, 900, 1.0);
  const ImageF quilt = constant_tile_quilt(q, [](int) { return 1.f; });
  const ImageF fit = interlace(quilt, q, lens);
  EXPECT_EQ(fit.at(0, 100, 1), 0.f);     // left bar
  EXPECT_EQ(fit.at(319, 100, 1), 0.f);   // right bar
  EXPECT_EQ(fit.at(160, 100, 1), 1.f);   // content
  EXPECT_EQ(fit.at(160, 0, 1), 1.f);     // full height
  InterlaceOptions o;
  o.overscan = true;
  const ImageF filled = interlace(quilt, q, lens, o);
  EXPECT_EQ(filled.at(0, 100, 1), 1.f);
}

TEST(Interlacer, TilesWithinAPixelOfThePanelAspectFillItWithNoBlackColumn) {
  const DisplayCalibration c = test::small_lkg_2k();  // 320x200, aspect 1.6
  const LensModel lens(c);
  // 5 x 3: tiles of 83x52 pixels (1.5962; 1.6 would be 83.2 wide), named by their pixels.
  const QuiltLayout q = quilt_layout(5, 3, 415, 156, 83.0 / 52.0);
  const ImageF filled = interlace(constant_tile_quilt(q, [](int) { return 1.f; }), q, lens);
  for (int row = 0; row < c.screen_h; ++row) {
    EXPECT_EQ(filled.at(0, row, 1), 1.f) << "row " << row;
    EXPECT_EQ(filled.at(c.screen_w - 1, row, 1), 1.f) << "row " << row;
  }
  const AspectFit fit = aspect_fit(c, q.aspect, false, q.tile_height());
  EXPECT_EQ(fit.scale_u, 1.0);
  EXPECT_EQ(fit.scale_v, 1.0);
  // Two pixels off is a different view aspect: fitted with bars, as before.
  EXPECT_GT(aspect_fit(c, 81.0 / 52.0, false, 52).scale_u, 1.0);
}

TEST(Interlacer, EveryRealCalibrationInterlacesToItsPanelSize) {
  for (const auto& file : test::fixture_calibrations()) {
    SCOPED_TRACE(file.string());
    const DisplayCalibration c = display::read_visual_json(file);
    const LensModel lens(c);
    const QuiltLayout q = quilt_layout(5, 9, 250, 450, double(c.screen_w) / c.screen_h);
    const ImageF quilt = constant_tile_quilt(q, [&](int k) { return (k + 0.5f) / q.views; });
    const ImageF panel = interlace(quilt, q, lens);
    EXPECT_EQ(panel.width, c.screen_w);
    EXPECT_EQ(panel.height, c.screen_h);
    // Spot-check: each subpixel shows the view its own lens-model fraction selects.
    for (int i = 0; i < 200; ++i) {
      const int x = (i * 7919) % c.screen_w, row = (i * 104729) % c.screen_h, ch = i % 3;
      const int expected = LensModel::view_index(lens.subpixel_view_fraction(x, row, ch), q.views);
      EXPECT_EQ(int(std::lround(panel.at(x, row, ch) * q.views - 0.5)), expected);
    }
  }
}

TEST(Interlacer, RejectsAQuiltOfTheWrongSize) {
  const DisplayCalibration c = test::small_lkg_2k();
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(5, 9, 500, 900, 1.6);
  EXPECT_THROW(interlace(ImageF(400, 900, 3), q, lens), InputError);
}

TEST(QuiltFile, TilingComesFromTheFileNameUnlessGiven) {
  const auto q = resolve_quilt_layout("dir/scene_qs8x6a0.75.png", 3360, 3360, {}, 1.0);
  EXPECT_EQ(q.cols, 8);
  EXPECT_EQ(q.rows, 6);
  EXPECT_EQ(q.views, 48);
  EXPECT_DOUBLE_EQ(q.aspect, 0.75);
  EXPECT_EQ(q.tile_width(), 420);
  QuiltOverrides o;
  o.cols = 5;
  o.rows = 9;
  o.views = 40;
  const auto g = resolve_quilt_layout("plain.png", 4096, 4096, o, 1.6);
  EXPECT_EQ(g.views, 40);
  EXPECT_DOUBLE_EQ(g.aspect, 1.6);
}

TEST(QuiltFile, UnknownTilingOrTooManyViewsIsAnInputError) {
  EXPECT_THROW(resolve_quilt_layout("plain.png", 100, 100, {}, 1.0), InputError);
  QuiltOverrides o;
  o.views = 50;
  EXPECT_THROW(resolve_quilt_layout("q_qs5x9a1.png", 100, 100, o, 1.0), InputError);
  EXPECT_THROW(resolve_quilt_layout("q_qs500x9a1.png", 100, 100, {}, 1.0), InputError);
}

}  // namespace
}  // namespace lfd::interlace
