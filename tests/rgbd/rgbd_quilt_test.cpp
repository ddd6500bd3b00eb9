// The CPU reference of RGB-D to quilt on the layered fixture (tests/rgbd/rgbd_fixture.hpp):
// every layer moves by the pixels the view model says (computed here from the quilt's view
// positions, not through the library), the focus plane stays, inversion flips the direction,
// chroma depth gives the same depths, holes are filled from the background side.
#include "rgbd/rgbd_quilt.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "rgbd/rgbd_view_model.hpp"
#include "tests/rgbd/rgbd_fixture.hpp"
#include "util/error.hpp"

namespace lfd::rgbd {
namespace {

using test::layer_code;
using test::Layer;

constexpr int kW = 96, kH = 64;  // the colour half; tiles of the same size

render::QuiltLayout fixture_layout(int views = 9, int cols = 3, int rows = 3) {
  render::QuiltLayout q;
  q.cols = cols;
  q.rows = rows;
  q.views = views;
  q.aspect = double(kW) / kH;
  q.width = cols * kW;
  q.height = rows * kH;
  return q;
}

// The known truth of docs/rgbd.md "The view model", written out from its definitions: view j of
// V at s_j = (j + 0.5)/V - 1/2 sees a pixel of depth d shifted by
// 2 s_j tan(cone/2) / tan(fov_x/2) * (depthiness 0.1 (0.5 - d) + focus) * W / 2 pixels, the
// camera's vertical field of view 40 degrees and square pixels.
double expected_shift_px(int view, int views, double d, const RgbdOptions& o, double cone_deg = 40) {
  const double s = (view + 0.5) / views - 0.5;
  const double deg = std::numbers::pi / 180;
  const double tan_fov_x = std::tan(20 * deg) * kW / kH;
  const double p = 2 * s * std::tan(cone_deg / 2 * deg) / tan_fov_x;
  return p * (o.depthiness * 0.1 * (0.5 - d) + o.focus) * kW / 2;
}

// The tile of view j, top-down, as one image.
ImageF tile(const ImageF& quilt, const render::QuiltLayout& q, int view) {
  ImageF t(q.tile_width(), q.tile_height(), 3);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x)
      for (int c = 0; c < 3; ++c)
        t.at(x, y, c) = quilt.at(q.tile_x(view) + x, q.tile_y_top_down(view) + y, c);
  return t;
}

// Where source column x of `layer` (on a row through it) lands in the view: its centre
// x + 0.5 moved by the expected shift, in the pixel it falls in.
int expected_column(int x, const Layer& layer, int view, int views, const RgbdOptions& o) {
  return int(std::floor(x + 0.5 + expected_shift_px(view, views, layer.depth, o)));
}

// Checks that interior columns of `layer` land where the view model says on a row through it.
void expect_layer_lands(const ImageF& quilt, const render::QuiltLayout& q, const Layer& layer,
                        int view, const RgbdOptions& o) {
  const ImageF t = tile(quilt, q, view);
  const int y = (layer.row0 + layer.row1) / 2;
  for (int x = layer.col0 + 8; x < layer.col1 - 8; x += 5) {
    const int landed = expected_column(x, layer, view, q.views, o);
    SCOPED_TRACE(testing::Message() << "view " << view << " layer " << layer.id << " column " << x
                                    << " shift " << expected_shift_px(view, q.views, layer.depth, o));
    EXPECT_FLOAT_EQ(t.at(landed, y, 0), test::column_code(x, kW));
    EXPECT_FLOAT_EQ(t.at(landed, y, 1), layer_code(layer.id));
  }
}

TEST(RgbdQuilt, EachLayerMovesByTheViewModelsPixels) {
  for (const double depthiness : {1.5, 4.0}) {
    RgbdOptions o;
    o.depthiness = depthiness;
    const auto q = fixture_layout();
    const ImageF quilt = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q);
    // The outer views move the near band by more than two pixels: the test can fail.
    EXPECT_GT(std::abs(expected_shift_px(0, 9, 1.0, o)), 2.0);
    for (const int view : {0, 2, 4, 6, 8}) {
      expect_layer_lands(quilt, q, test::near_layer(kW, kH), view, o);
      Layer background = test::background_layer(kW, kH);
      background.row0 = 0, background.row1 = kH / 4;  // rows with nothing in front
      expect_layer_lands(quilt, q, background, view, o);
    }
  }
}

TEST(RgbdQuilt, NearContentMovesAgainstTheCameraAndFarContentWithIt) {
  const RgbdOptions o;
  // View 0 is the leftmost camera: near content moves right in it, far content left.
  EXPECT_GT(expected_shift_px(0, 9, 1.0, o), 0.0);
  EXPECT_LT(expected_shift_px(0, 9, 0.0, o), 0.0);
  const auto geometry = rgbd_quilt_geometry(fixture_layout());
  EXPECT_NEAR(view_shift_px(geometry, 0, kW, 1.0f, o), expected_shift_px(0, 9, 1.0, o), 1e-4);
  EXPECT_NEAR(view_shift_px(geometry, 8, kW, 0.25f, o), expected_shift_px(8, 9, 0.25, o), 1e-4);
}

TEST(RgbdQuilt, TheFocusPlaneDoesNotMove) {
  RgbdOptions o;
  const auto q = fixture_layout();
  const ImageF quilt = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q);
  const Layer focus = test::focus_layer(kW, kH);
  for (int view = 0; view < q.views; ++view) {
    const ImageF t = tile(quilt, q, view);
    for (int y = focus.row0; y < focus.row1; ++y)
      for (int x = focus.col0; x < focus.col1; ++x)
        ASSERT_FLOAT_EQ(t.at(x, y, 0), test::column_code(x, kW)) << view << " " << x << " " << y;
  }
  // With focus set, the zero-parallax depth moves to d_0 and a layer there stays put.
  o.focus = 0.03;
  const double d0 = zero_parallax_depth(o);
  // 0.5 + focus / (depthiness kReliefRatio) = 0.5 + 0.03 / (1.5 x 0.1) (docs/rgbd.md).
  EXPECT_NEAR(d0, 0.7, 1e-12);
  EXPECT_NEAR(relief_z_ratio(float(d0), o), 0.0f, 1e-7f);
  EXPECT_NEAR(expected_shift_px(0, 9, d0, o), 0.0, 1e-12);
}

TEST(RgbdQuilt, InversionFlipsTheDirectionOfEveryShift) {
  RgbdOptions o;
  o.depthiness = 4.0;
  const auto q = fixture_layout();
  // The same frame read with the depth inverted: the far background becomes near and moves
  // the other way by the same pixels (focus 0: the relief is symmetric about d = 0.5).
  RgbdOptions inverted = o;
  inverted.depth_inversion = true;
  const ImageF quilt = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), inverted, q);
  Layer background_read_as_near = test::background_layer(kW, kH);
  background_read_as_near.row0 = 0, background_read_as_near.row1 = kH / 4;
  background_read_as_near.depth = 1.0f;
  EXPECT_NEAR(expected_shift_px(0, 9, 0.0, o), -expected_shift_px(0, 9, 1.0, o), 1e-12);
  for (const int view : {0, 8}) expect_layer_lands(quilt, q, background_read_as_near, view, o);
  // And a frame written inverted (black near) read with inversion is the original quilt.
  const ImageF original = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q);
  const ImageF round_trip = render_rgbd_quilt(
      test::layered_rgbd_frame(kW, kH, o.depth_loc, false, true), inverted, q);
  EXPECT_EQ(original.pixels, round_trip.pixels);
}

TEST(RgbdQuilt, ChromaDepthDecodesToTheSameDepthsAndViews) {
  RgbdOptions grey;
  grey.depthiness = 3.0;
  RgbdOptions chroma = grey;
  chroma.chroma_depth = true;
  const RgbdSource a = resample_rgbd(test::layered_rgbd_frame(kW, kH, grey.depth_loc), grey, kW, kH);
  const RgbdSource b =
      resample_rgbd(test::layered_rgbd_frame(kW, kH, grey.depth_loc, true), chroma, kW, kH);
  for (size_t i = 0; i < a.depth.size(); ++i) ASSERT_NEAR(a.depth[i], b.depth[i], 1e-5f) << i;
  const auto q = fixture_layout();
  const ImageF qa = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, grey.depth_loc), grey, q);
  const ImageF qb =
      render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, grey.depth_loc, true), chroma, q);
  EXPECT_EQ(qa.pixels, qb.pixels);
}

TEST(RgbdQuilt, EveryDepthLocationGivesTheSameQuilt) {
  const auto q = fixture_layout();
  RgbdOptions o;
  const ImageF reference = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q);
  for (const auto loc : {DepthLocation::top, DepthLocation::bottom, DepthLocation::left}) {
    o.depth_loc = loc;
    EXPECT_EQ(render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, loc), o, q).pixels,
              reference.pixels)
        << depth_location_name(loc);
  }
}

TEST(RgbdQuilt, HolesAreFilledFromTheBackgroundSide) {
  RgbdOptions o;
  o.depthiness = 4.0;
  const auto q = fixture_layout();
  const RgbdSource source =
      resample_rgbd(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q.tile_width(), q.tile_height());
  const auto geometry = rgbd_quilt_geometry(q);
  const int view = q.views - 1;  // the rightmost camera: the near band moves left
  WarpedView warped = warp_view(source, o, view_shift_px_per_z_ratio(geometry, view, kW));
  size_t holes = 0;
  for (const float d : warped.depth) holes += d == kHole;
  ASSERT_GT(holes, 0u);  // disocclusions and the tile edge opened
  EXPECT_EQ(fill_holes(warped), holes);
  for (const float d : warped.depth) ASSERT_NE(d, kHole);
  // No black left: every colour of the fixture is bright.
  for (int y = 0; y < warped.height; ++y)
    for (int x = 0; x < warped.width; ++x)
      ASSERT_GT(warped.colour.at(x, y, 0) + warped.colour.at(x, y, 1), 0.25f) << x << " " << y;
  // Right of the near band, where it moved away, the filled pixels are background.
  const Layer near = test::near_layer(kW, kH);
  const int y = (near.row0 + near.row1) / 2;
  const int band_end = expected_column(near.col1 - 1, near, view, q.views, o) + 1;
  Layer background = test::background_layer(kW, kH);
  const int background_start = expected_column(near.col1, background, view, q.views, o);
  ASSERT_LT(band_end, background_start);
  for (int x = band_end; x < background_start; ++x)
    EXPECT_FLOAT_EQ(warped.colour.at(x, y, 1), layer_code(0)) << x;
}

// depth_cutoff's known truth (docs/rgbd.md "Depth cutoff"): the quilt with a cutoff is the quilt
// without it where every pixel that shows a layer farther than the cutoff is black, and every
// other pixel is unchanged (removed pixels keep their depth, so nothing moves and holes fill
// from the same side).
void expect_cutoff_removes_layers_below(double cutoff, const std::vector<int>& removed_ids) {
  RgbdOptions o;
  o.depthiness = 4.0;  // wide disocclusions: holes fill from the (removed) background side
  const auto q = fixture_layout();
  const ImageF frame = test::layered_rgbd_frame(kW, kH, o.depth_loc);
  const ImageF whole = render_rgbd_quilt(frame, o, q);
  o.depth_cutoff = cutoff;
  const ImageF cut = render_rgbd_quilt(frame, o, q);
  size_t removed = 0, kept = 0;
  for (int y = 0; y < q.height; ++y)
    for (int x = 0; x < q.width; ++x) {
      // The layer a pixel shows, by its code (bilinear colour may blend a pixel's code with its
      // neighbour's by a float rounding where a layer ends; the depth is the nearest texel's).
      const float g = whole.at(x, y, 1);
      const bool gone = std::any_of(removed_ids.begin(), removed_ids.end(),
                                    [&](int id) { return std::abs(g - layer_code(id)) < 0.01f; });
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(cut.at(x, y, c), gone ? 0.0f : whole.at(x, y, c)) << x << " " << y << " " << c;
      (gone ? removed : kept) += 1;
    }
  EXPECT_EQ(removed > 0, !removed_ids.empty());
  EXPECT_GT(kept, 0u);
}

TEST(RgbdQuilt, DepthCutoffRemovesWhatLiesFartherThanIt) {
  SCOPED_TRACE("between the background (d 0) and the focus band (d 0.5)");
  expect_cutoff_removes_layers_below(0.25, {0});
  SCOPED_TRACE("between the focus band and the near band (d 1)");
  expect_cutoff_removes_layers_below(0.75, {0, 1});
  SCOPED_TRACE("0, the default, removes nothing");
  expect_cutoff_removes_layers_below(0.0, {});
}

TEST(RgbdQuilt, DepthCutoffAppliesToTheDecodedDepthAfterInversion) {
  // Inverted depth (black near): the near band is written 0 and decodes to 1, so a cutoff of
  // 0.75 keeps it and removes the rest, as without inversion.
  RgbdOptions o;
  o.depth_inversion = true;
  o.depth_cutoff = 0.75;
  const auto q = fixture_layout();
  const ImageF quilt = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc, false, true), o, q);
  const Layer near = test::near_layer(kW, kH), focus = test::focus_layer(kW, kH);
  const ImageF t = tile(quilt, q, q.views / 2);
  EXPECT_FLOAT_EQ(t.at(kW / 2, (near.row0 + near.row1) / 2, 1), layer_code(near.id));
  EXPECT_EQ(t.at(kW / 2, (focus.row0 + focus.row1) / 2, 1), 0.0f);
  EXPECT_EQ(t.at(2, 2, 1), 0.0f);
}

TEST(RgbdQuilt, ViewsSitInTheirTilesAndTheRestIsBlack) {
  auto q = fixture_layout(7, 3, 3);  // two empty tiles
  q.width += 2;                      // and a margin (the tiles stay 96 x 64)
  q.height += 2;
  const RgbdOptions o;
  const ImageF quilt = render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q);
  // View 0 bottom-left, view 6 top-left: the focus band at its place in each.
  for (const int view : {0, 3, 6})
    EXPECT_FLOAT_EQ(tile(quilt, q, view).at(kW / 2, kH * 3 / 8, 0), test::column_code(kW / 2, kW));
  EXPECT_EQ(quilt.at(q.width - 1, q.height - 1, 0), 0.0f);
  EXPECT_EQ(quilt.at(q.tile_x(8) + 3, q.tile_y_top_down(8) + 3, 1), 0.0f);  // tile 8: no view
}

TEST(RgbdQuilt, ZoomMagnifiesAboutTheCropCentre) {
  RgbdOptions o;
  o.zoom = 2.0;
  const auto q = fixture_layout(1, 1, 1);  // one centred view: no parallax
  const ImageF frame = test::layered_rgbd_frame(kW, kH, o.depth_loc);
  ImageF t = render_rgbd_quilt(frame, o, q);
  // Tile column x shows source position W/4 + (x + 0.5)/2: the middle half of the colour.
  EXPECT_NEAR(t.at(0, kH / 2, 0), test::column_code(kW / 4, kW), 0.01f);
  EXPECT_NEAR(t.at(kW - 1, kH / 2, 0), test::column_code(3 * kW / 4 - 1, kW), 0.01f);
  // crop_pos_x = 1 moves the centre to the right edge: the left half shows the right half of
  // the colour, the right half is beyond it (black).
  o.zoom = 1.0;
  o.crop_pos_x = 1.0;
  t = render_rgbd_quilt(frame, o, q);
  EXPECT_NEAR(t.at(0, 2, 0), test::column_code(kW / 2, kW), 1e-5f);
  EXPECT_EQ(t.at(kW - 1, 2, 0), 0.0f);
}

TEST(RgbdQuilt, TheQuiltLayoutOfAFrameHasItsColourAspect) {
  const auto q = rgbd_quilt_layout(3840, 1080, DepthLocation::right, 45, 256);
  EXPECT_DOUBLE_EQ(q.aspect, 1920.0 / 1080.0);
  EXPECT_EQ(q.tile_height(), 256);
  EXPECT_EQ(q.tile_width(), 455);
  EXPECT_EQ(q.cols * q.rows, 45);
  EXPECT_EQ(q.views, 45);
  const auto native = rgbd_quilt_layout(200, 100, DepthLocation::right, 4);
  EXPECT_EQ(native.tile_width(), 100);
  EXPECT_EQ(native.tile_height(), 100);
}

TEST(RgbdQuilt, BadInputIsAnInputError) {
  const auto q = fixture_layout();
  RgbdOptions o;
  EXPECT_THROW(render_rgbd_quilt(ImageF(), o, q), InputError);
  EXPECT_THROW(render_rgbd_quilt(ImageF(1, 8, 3), o, q), InputError);
  o.depthiness = 0.0;
  EXPECT_THROW(render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q), InputError);
  auto bad = q;
  bad.views = 10;  // more views than tiles
  EXPECT_THROW(render_rgbd_quilt(test::layered_rgbd_frame(kW, kH, o.depth_loc), RgbdOptions{}, bad),
               InputError);
}

}  // namespace
}  // namespace lfd::rgbd
