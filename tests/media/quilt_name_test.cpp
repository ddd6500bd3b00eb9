// The `_qsCxRaA` convention: parsed as Looking Glass software writes it, bounded against hostile
// names, and a name that lies about the picture is refused naming the file.
#include <gtest/gtest.h>

#include "media/quilt_name.hpp"
#include "util/error.hpp"

namespace lfd::media {
namespace {

TEST(QuiltName, ParsesTheConventionFirstNumberColumns) {
  const auto q = parse_quilt_name("scene_qs5x9a1.6.png");
  ASSERT_TRUE(q);
  EXPECT_EQ(q->cols, 5);
  EXPECT_EQ(q->rows, 9);
  EXPECT_DOUBLE_EQ(q->aspect, 1.6);
  const auto portrait = parse_quilt_name("clip_qs8x6a0.75.mp4");
  ASSERT_TRUE(portrait);
  EXPECT_EQ(portrait->cols, 8);
  EXPECT_DOUBLE_EQ(portrait->aspect, 0.75);
  const auto integer = parse_quilt_name("x_qs7x7a1.mov");
  ASSERT_TRUE(integer);
  EXPECT_DOUBLE_EQ(integer->aspect, 1.0);
  const auto trailing_dot = parse_quilt_name("x_qs7x7a2.");
  ASSERT_TRUE(trailing_dot);
  EXPECT_DOUBLE_EQ(trailing_dot->aspect, 2.0);
}

TEST(QuiltName, TheFirstValidTagCounts) {
  const auto q = parse_quilt_name("a_qsx_qs11x6a0.5625_qs8x6a0.75.png");
  ASSERT_TRUE(q);
  EXPECT_EQ(q->cols, 11);
  EXPECT_EQ(q->rows, 6);
}

TEST(QuiltName, RefusesMissingOrOutOfBoundsNumbers) {
  for (const char* name : {"plain.png", "_qs5x9.png", "_qs5x9a.png", "_qs0x9a1.6", "_qs5x0a1.6", "_qs257x9a1",
                           "_qs99999999999x2a1", "_qs5x9a0.001", "_qs5x9a1000", "_qs5x9a1.00000000000000001",
                           "_QS5x9a1.6", "_qs-5x9a1", "_qs5X9a1"})
    EXPECT_FALSE(parse_quilt_name(name)) << name;
}

TEST(QuiltName, LayoutFromTheNameOrOverrides) {
  const auto q = quilt_layout_for("dir/scene_qs5x9a1.6.png", 4096, 4096, {}, 0.75);
  EXPECT_EQ(q.cols, 5);
  EXPECT_EQ(q.rows, 9);
  EXPECT_EQ(q.views, 45);
  EXPECT_EQ(q.width, 4096);
  interlace::QuiltOverrides o;
  o.cols = 8;
  o.rows = 6;
  const auto unnamed = quilt_layout_for("plain.png", 3360, 3360, o, 0.75);
  EXPECT_EQ(unnamed.cols, 8);
  EXPECT_DOUBLE_EQ(unnamed.aspect, 0.75);  // the display's
}

TEST(QuiltName, ALyingNameIsAnErrorNamingTheFile) {
  // A 768x768 8x6 quilt named as 64x2: 12-pixel-wide tiles 32 times taller than the aspect.
  try {
    quilt_layout_for("/tmp/lying_qs64x2a0.75.png", 768, 768, {}, 0.75);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/tmp/lying_qs64x2a0.75.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(quilt_layout_for("tiny_qs5x9a1.6.png", 40, 40, {}, 1.0), InputError);       // 8x4 px tiles
  EXPECT_THROW(quilt_layout_for("plain.png", 100, 100, {}, 1.0), InputError);              // no tiling at all
  interlace::QuiltOverrides too_many;
  too_many.views = 60;
  EXPECT_THROW(quilt_layout_for("s_qs5x9a1.png", 500, 900, too_many, 1.0), InputError);  // 60 views in 45 tiles
  // The real quilts pass: the 16" Gen2's 4096^2 5x9 at 1.6 (tiles 1.8 wide), the Go's 11x6.
  EXPECT_NO_THROW(quilt_layout_for("a_qs5x9a1.6.png", 4096, 4096, {}, 1.0));
  EXPECT_NO_THROW(quilt_layout_for("a_qs11x6a0.5625.png", 4092, 4092, {}, 1.0));
}

}  // namespace
}  // namespace lfd::media
