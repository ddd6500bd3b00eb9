// The GL twin (rgbd::GlRgbdViews) against the CPU reference (rgbd::render_rgbd_quilt) on the
// layered fixture, on Mesa llvmpipe through EGL surfaceless: the tolerance of docs/rgbd.md
// "On the GPU" (at least 99.9 % of quilt pixels within 1/255 in every channel; the rest are
// pixels whose landing column sits on a rounding boundary where GLSL's float arithmetic and the
// CPU's may round differently).
#include "rgbd/gl_rgbd_views.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "rgbd/rgbd_quilt.hpp"
#include "tests/rgbd/rgbd_fixture.hpp"
#include "util/error.hpp"

namespace lfd::rgbd {
namespace {

constexpr int kW = 96, kH = 64;

render::QuiltLayout layout(int views, int cols, int rows, int margin_x = 0, int margin_y = 0) {
  render::QuiltLayout q;
  q.cols = cols;
  q.rows = rows;
  q.views = views;
  q.aspect = double(kW) / kH;
  q.width = cols * kW + margin_x;
  q.height = rows * kH + margin_y;
  return q;
}

// The fraction of pixels whose channels all agree within 1/255.
double agreeing_fraction(const ImageF& a, const ImageF& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  size_t agree = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      bool same = true;
      for (int c = 0; c < 3; ++c) same &= std::abs(a.at(x, y, c) - b.at(x, y, c)) <= 1.0f / 255;
      agree += same;
    }
  return double(agree) / (double(a.width) * a.height);
}

void expect_gl_matches_cpu(const ImageF& frame, const RgbdOptions& o, const render::QuiltLayout& q,
                           double cone_deg = 40.0) {
  const ImageF cpu = render_rgbd_quilt(frame, o, q, cone_deg);
  const ImageF gl = render_rgbd_quilt_on_gpu(frame, o, q, cone_deg);
  EXPECT_GE(agreeing_fraction(cpu, gl), 0.999);
}

TEST(GlRgbdViews, MatchesTheCpuReferenceWithBridgeJsDefaults) {
  gpu::HeadlessContext context;
  expect_gl_matches_cpu(test::layered_rgbd_frame(kW, kH, DepthLocation::right), RgbdOptions{},
                        layout(9, 3, 3));
}

TEST(GlRgbdViews, MatchesWithStrongReliefFocusInversionAndChromaDepth) {
  gpu::HeadlessContext context;
  RgbdOptions o;
  o.depthiness = 4.0;
  o.focus = -0.04;
  o.depth_inversion = true;
  o.chroma_depth = true;
  o.depth_loc = DepthLocation::top;
  expect_gl_matches_cpu(test::layered_rgbd_frame(kW, kH, o.depth_loc, true, true), o,
                        layout(16, 4, 4), 54.0);
}

TEST(GlRgbdViews, MatchesWithADepthCutoff) {
  gpu::HeadlessContext context;
  RgbdOptions o;
  o.depthiness = 4.0;
  o.depth_cutoff = 0.75;  // the background and the focus band removed, the near band kept
  expect_gl_matches_cpu(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, layout(9, 3, 3));
}

TEST(GlRgbdViews, MatchesWithZoomCropEmptyTilesAndAMargin) {
  gpu::HeadlessContext context;
  RgbdOptions o;
  o.zoom = 1.7;
  o.crop_pos_x = -0.4;
  o.crop_pos_y = 0.3;
  o.depth_loc = DepthLocation::left;
  expect_gl_matches_cpu(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, layout(7, 3, 3, 5, 3));
}

TEST(GlRgbdViews, MatchesOnATileSizeOtherThanTheFrames) {
  gpu::HeadlessContext context;
  RgbdOptions o;
  o.depthiness = 2.5;
  render::QuiltLayout q = layout(8, 4, 2);
  q.width = 4 * 61;  // tiles of 61 x 43: every tile pixel resamples between frame pixels
  q.height = 2 * 43;
  expect_gl_matches_cpu(test::layered_rgbd_frame(kW, kH, o.depth_loc), o, q);
}

TEST(GlRgbdViews, KeepsTheCallersFramebufferAndReusesItsIntermediates) {
  gpu::HeadlessContext context;
  const auto q = layout(9, 3, 3);
  const ImageF frame = test::layered_rgbd_frame(kW, kH, DepthLocation::right);
  const gpu::Texture frame_texture = gpu::texture_from_image(frame);
  gpu::Texture quilt(GL_RGBA8, q.width, q.height);
  GlRgbdViews views;
  glViewport(1, 2, 3, 4);
  RgbdOptions o;
  views.render(frame_texture, o, q, quilt);
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 3);
  EXPECT_EQ(viewport[3], 4);
  // A second frame with other options through the same object: the CPU's quilt again (RGBA8:
  // within one 8-bit step).
  o.depthiness = 3.0;
  views.render(RgbdFrameTexture{frame_texture.id(), frame.width, frame.height}, o, q, quilt);
  const ImageF gl = gpu::image_from_texture(quilt);
  EXPECT_GE(agreeing_fraction(render_rgbd_quilt(frame, o, q), gl), 0.999);
  // The measure tells quilts apart: the first options' quilt differs on the moved bands.
  EXPECT_LT(agreeing_fraction(render_rgbd_quilt(frame, RgbdOptions{}, q), gl), 0.99);
}

TEST(GlRgbdViews, ReadsATopDownFrameTextureWithoutAFlip) {
  gpu::HeadlessContext context;
  const auto q = layout(9, 3, 3);
  RgbdOptions o;
  o.depthiness = 3.0;
  o.crop_pos_y = 0.4;  // not symmetric top to bottom
  const ImageF frame = test::layered_rgbd_frame(kW, kH, DepthLocation::bottom);
  o.depth_loc = DepthLocation::bottom;
  // The frame's rows stored top row first: texture_from_image flips, so give it the rows
  // reversed.
  ImageF reversed(frame.width, frame.height, frame.channels);
  for (int y = 0; y < frame.height; ++y)
    std::copy_n(frame.row(frame.height - 1 - y), size_t(frame.width) * frame.channels,
                reversed.row(y));
  const gpu::Texture top_down = gpu::texture_from_image(reversed);
  gpu::Texture quilt(GL_RGBA32F, q.width, q.height);
  GlRgbdViews views;
  views.render(RgbdFrameTexture{top_down.id(), frame.width, frame.height, true}, o, q, quilt);
  EXPECT_GE(agreeing_fraction(render_rgbd_quilt(frame, o, q), gpu::image_from_texture(quilt)),
            0.999);
}

TEST(GlRgbdViews, AWrongQuiltTextureOrFrameIsAnInputError) {
  gpu::HeadlessContext context;
  const auto q = layout(9, 3, 3);
  const gpu::Texture frame = gpu::texture_from_image(test::layered_rgbd_frame(kW, kH, DepthLocation::right));
  GlRgbdViews views;
  gpu::Texture small(GL_RGBA8, q.width - 1, q.height);
  EXPECT_THROW(views.render(frame, RgbdOptions{}, q, small), InputError);
  gpu::Texture quilt(GL_RGBA8, q.width, q.height);
  EXPECT_THROW(views.render(RgbdFrameTexture{0, 10, 10}, RgbdOptions{}, q, quilt), InputError);
  EXPECT_THROW(views.render(RgbdFrameTexture{frame.id(), 1, 10}, RgbdOptions{}, q, quilt), InputError);
  RgbdOptions bad;
  bad.zoom = 9;
  EXPECT_THROW(views.render(frame, bad, q, quilt), InputError);
}

}  // namespace
}  // namespace lfd::rgbd
