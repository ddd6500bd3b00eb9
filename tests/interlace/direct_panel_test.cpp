// The direct panel pass (interlace/direct_panel.hpp) against the quilt path (swizzle blend +
// interlacer) on planes of flat-coloured layers built by hand, so nothing but the two passes is
// under test.
#include "interlace/direct_panel.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "display/visual_json.hpp"
#include "interlace/interlacer.hpp"
#include "render/per_view_quilt.hpp"
#include "render/swizzle_blend.hpp"
#include "tests/interlace/flat_layer_planes.hpp"
#include "tests/support/small_displays.hpp"
#include "tests/test_data.hpp"

namespace lfd::interlace {
namespace {

struct Comparison {
  int on_view = 0;      // subpixels whose fraction lies on a view centre, in flat quilt texels
  double max_diff = 0;  // the largest |direct - quilt| among them
  int differing = 0;    // subpixels anywhere where the two differ by more than 1/255
};

// Subpixels within 1e-4 / V of a view centre (about 2e-4 of them: 40 on a 320x200 panel), where the quilt texels the interlacer blends are
// all equal (away from a layer's edge), compared between the two panels.
Comparison compare_on_views(const test_planes::FlatLayerScene& s, const display::LensModel& lens, bool invert) {
  render::QuiltLayout layout = render::make_quilt_layout(s.geometry, 4, 2);
  ImageF quilt(layout.width, layout.height, 3, 0.0f);
  render::swizzle_blend(s.planes, s.geometry, s.ref, layout, render::PlaneFilter::kNearest, s.background, quilt);
  InterlaceOptions io;
  io.invert_views = invert;
  const Interlacer interlacer(lens, layout, io);
  const ImageF via_quilt = interlacer.interlace(quilt);
  DirectPanelOptions dopt;
  dopt.filter = render::PlaneFilter::kNearest;  // as the swizzle above
  dopt.background = s.background;
  dopt.invert_views = invert;
  const ImageF direct = render_direct_panel(s.planes, s.geometry, s.ref, lens, dopt);
  EXPECT_EQ(direct.width, via_quilt.width);
  EXPECT_EQ(direct.height, via_quilt.height);
  Comparison out;
  const int views = s.geometry.views;
  for (int row = 0; row < direct.height; ++row)
    for (int x = 0; x < direct.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(double(direct.at(x, row, c)) - via_quilt.at(x, row, c));
        if (d > 1.0 / 255) ++out.differing;
        const SubpixelSample sample = interlacer.sample_for(x, row, c);
        if (!sample.inside) continue;
        const double t = panel_view_fraction(lens, invert, x, row, c) * views - 0.5;
        if (std::abs(t - std::round(t)) > 1e-4) continue;
        // The four texels the bilinear tile lookup reads must agree (no edge among them).
        const float a = interlacer.sample_tile(quilt, sample.view_a, sample.tile_u, sample.tile_v, c);
        bool flat = true;
        for (double du : {-1.0, 1.0})
          for (double dv : {-1.0, 1.0}) {
            const double u = sample.tile_u + du / layout.tile_width(), v = sample.tile_v + dv / layout.tile_height();
            if (std::abs(interlacer.sample_tile(quilt, sample.view_a, u, v, c) - a) > 1e-6) flat = false;
          }
        if (!flat) continue;
        ++out.on_view;
        out.max_diff = std::max(out.max_diff, d);
      }
  return out;
}

TEST(DirectPanel, EqualsTheQuiltPathWhereAFractionFallsOnAView) {
  const test_planes::FlatLayerScene s = test_planes::flat_layer_scene(160, 100, 8);
  const display::LensModel lens(test::small_lkg_2k(0.1));
  for (bool invert : {false, true}) {
    const Comparison c = compare_on_views(s, lens, invert);
    EXPECT_GT(c.on_view, 20) << "invert " << invert;
    EXPECT_LT(c.max_diff, 1e-5) << "invert " << invert;
    // Elsewhere the direct pass shows the layers' edges at their own angle, not at a view's.
    EXPECT_GT(c.differing, 100) << "invert " << invert;
  }
}

TEST(DirectPanel, EqualsTheQuiltPathOnGen3SubpixelCells) {
  const test_planes::FlatLayerScene s = test_planes::flat_layer_scene(108, 192, 8);
  const display::LensModel lens(test::small_gen3_portrait_template());
  const Comparison c = compare_on_views(s, lens, false);
  EXPECT_GT(c.on_view, 20);
  EXPECT_LT(c.max_diff, 1e-5);
}

TEST(DirectPanel, ViewPositionOfAFractionIsTheQuiltViewCentre) {
  const test_planes::FlatLayerScene s = test_planes::flat_layer_scene(32, 20, 7);
  for (int j = 0; j < 7; ++j)
    EXPECT_FLOAT_EQ(s.geometry.view_offset_at(view_position_of_fraction((j + 0.5) / 7)), s.geometry.view_offset(j));
}

}  // namespace
}  // namespace lfd::interlace
