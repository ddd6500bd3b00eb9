// Frame pacing figures (viewer/frame_pacing.hpp): median and nearest-rank 99th percentile.
#include <gtest/gtest.h>

#include "viewer/frame_pacing.hpp"

namespace lfd::viewer {
namespace {

TEST(FramePacing, MedianAndP99OfTheWindow) {
  FramePacing pacing(200);
  EXPECT_EQ(pacing.figures().frames, 0u);
  for (int i = 0; i < 98; ++i) pacing.add(0.010);
  pacing.add(0.050);
  pacing.add(0.200);  // 100 intervals: the p99 is the 99th smallest, the median 10 ms
  const PacingFigures f = pacing.figures();
  EXPECT_EQ(f.frames, 100u);
  EXPECT_DOUBLE_EQ(f.median_s, 0.010);
  EXPECT_DOUBLE_EQ(f.p99_s, 0.050);
}

TEST(FramePacing, KeepsOnlyTheLastWindow) {
  FramePacing pacing(3);
  for (double s : {1.0, 1.0, 1.0, 0.002, 0.004, 0.003}) pacing.add(s);
  const PacingFigures f = pacing.figures();
  EXPECT_EQ(f.frames, 3u);
  EXPECT_DOUBLE_EQ(f.median_s, 0.003);
  EXPECT_DOUBLE_EQ(f.p99_s, 0.004);
}

}  // namespace
}  // namespace lfd::viewer
