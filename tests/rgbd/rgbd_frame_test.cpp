// The split of a side-by-side frame and the depth decoding (grey, chroma, inverted).
#include "rgbd/rgbd_frame.hpp"

#include <string>

#include <gtest/gtest.h>

#include "tests/rgbd/rgbd_fixture.hpp"
#include "util/error.hpp"

namespace lfd::rgbd {
namespace {

TEST(RgbdFrame, SplitsEachSideAsBridgeJsNumbersIt) {
  // 2 = right (the default): colour left.
  RgbdSplit s = split_rgbd_frame(200, 100, DepthLocation::right);
  EXPECT_EQ(s.colour, (PixelRect{0, 0, 100, 100}));
  EXPECT_EQ(s.depth, (PixelRect{100, 0, 100, 100}));
  EXPECT_DOUBLE_EQ(s.colour_aspect(), 1.0);
  s = split_rgbd_frame(201, 100, DepthLocation::left);  // odd: the middle column is neither
  EXPECT_EQ(s.depth, (PixelRect{0, 0, 100, 100}));
  EXPECT_EQ(s.colour, (PixelRect{101, 0, 100, 100}));
  s = split_rgbd_frame(160, 90, DepthLocation::top);  // 0 = top: colour below
  EXPECT_EQ(s.depth, (PixelRect{0, 0, 160, 45}));
  EXPECT_EQ(s.colour, (PixelRect{0, 45, 160, 45}));
  s = split_rgbd_frame(160, 90, DepthLocation::bottom);
  EXPECT_EQ(s.colour, (PixelRect{0, 0, 160, 45}));
  EXPECT_EQ(s.depth, (PixelRect{0, 45, 160, 45}));
  EXPECT_DOUBLE_EQ(s.colour_aspect(), 160.0 / 45.0);
}

TEST(RgbdFrame, BottomUpRectanglesAreTheGlRowsOfTheSamePixels) {
  const RgbdSplit s = split_rgbd_frame(160, 90, DepthLocation::top);
  EXPECT_EQ(bottom_up(s.depth, 90), (PixelRect{0, 45, 160, 45}));   // the top half: upper rows
  EXPECT_EQ(bottom_up(s.colour, 90), (PixelRect{0, 0, 160, 45}));
}

TEST(RgbdFrame, AFrameTooSmallToSplitIsAnInputError) {
  EXPECT_THROW(split_rgbd_frame(1, 100, DepthLocation::right), InputError);
  EXPECT_THROW(split_rgbd_frame(100, 1, DepthLocation::top), InputError);
  EXPECT_THROW(split_rgbd_frame(0, 0, DepthLocation::right), InputError);
  try {
    split_rgbd_frame(1, 5, DepthLocation::left, "photo.png");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("photo.png"), std::string::npos);
  }
}

TEST(RgbdFrame, GreyDepthIsTheMeanAndInversionFlipsIt) {
  EXPECT_FLOAT_EQ(decode_depth(1, 1, 1, false, false), 1.0f);  // white: near
  EXPECT_FLOAT_EQ(decode_depth(0, 0, 0, false, false), 0.0f);
  EXPECT_FLOAT_EQ(decode_depth(0.3f, 0.3f, 0.3f, false, false), 0.3f);
  EXPECT_FLOAT_EQ(decode_depth(0.3f, 0.3f, 0.3f, false, true), 0.7f);
  EXPECT_FLOAT_EQ(decode_depth(0.0f, 0.0f, 0.0f, false, true), 1.0f);  // black near
}

TEST(RgbdFrame, ChromaDepthDecodesTheHueItWasEncodedWith) {
  for (int i = 0; i <= 100; ++i) {
    const float d = float(i) / 100.0f;
    float rgb[3];
    test::hue_to_rgb(chroma_hue_of_depth(d), rgb);
    EXPECT_NEAR(decode_depth(rgb[0], rgb[1], rgb[2], true, false), d, 1e-5f) << d;
    EXPECT_NEAR(decode_depth(rgb[0], rgb[1], rgb[2], true, true), 1.0f - d, 1e-5f) << d;
  }
  EXPECT_FLOAT_EQ(decode_depth(1, 0, 0, true, false), 1.0f);     // red: near
  EXPECT_FLOAT_EQ(decode_depth(0, 0, 1, true, false), 0.0f);     // blue: far
  EXPECT_FLOAT_EQ(decode_depth(0.5f, 0.5f, 0.5f, true, false), 0.0f);  // no hue: far
  EXPECT_FLOAT_EQ(decode_depth(1, 0, 0.9f, true, false), 1.0f);  // magenta near red: near
  EXPECT_FLOAT_EQ(decode_depth(0.6f, 0, 1, true, false), 0.0f);  // violet near blue: far
}

}  // namespace
}  // namespace lfd::rgbd
