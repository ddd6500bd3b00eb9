// Per-view voxel quilts: each tile is its view's render through the off-axis camera, and a
// voxel off the focal plane moves between views.
#include <gtest/gtest.h>

#include "voxel/voxel_quilt.hpp"
#include "voxel_test_scenes.hpp"

namespace lfd::voxel {
namespace {

TEST(VoxelQuilt, EachTileIsItsViewAndANearVoxelShowsParallax) {
  scene::VoxelScene s = testing::empty_scene();
  testing::add_voxel(s, {3, 3, 1}, 3, 50.0f, {1, 0, 0});  // edge 1/8, in front of the centre
  const render::Camera base = render::make_look_at_camera({0, 0, -2}, {0, 0, 0}, {0, -1, 0}, 0.6f, 24, 24);
  const render::QuiltGeometry g = render::make_quilt_geometry(base, 2.0f, 40.0f, 3);
  const render::QuiltLayout layout = render::make_quilt_layout(g, 3, 1);
  const ImageF quilt = render_voxel_quilt_per_view(s, g, layout);
  float red_x[3];
  for (int j = 0; j < 3; ++j) {
    const ImageF tile = render::extract_view(quilt, layout, j);
    const render::RasterImage view = render_voxel_view(s, g, j);
    ASSERT_EQ(tile.pixels, view.rgb) << "view " << j;
    // The red voxel's horizontal centroid in this view.
    double sum = 0, weight = 0;
    for (int y = 0; y < tile.height; ++y)
      for (int x = 0; x < tile.width; ++x) {
        sum += x * tile.at(x, y, 0);
        weight += tile.at(x, y, 0);
      }
    ASSERT_GT(weight, 1.0);
    red_x[j] = float(sum / weight);
  }
  // In front of the focal plane (the voxel is nearer than the look-at point), content moves
  // against the camera: monotonic across views, with the centre view in between.
  EXPECT_GT(std::abs(red_x[2] - red_x[0]), 1.0f);
  EXPECT_LT(std::min(red_x[0], red_x[2]), red_x[1]);
  EXPECT_GT(std::max(red_x[0], red_x[2]), red_x[1]);
}

}  // namespace
}  // namespace lfd::voxel
