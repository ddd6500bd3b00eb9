// The exact voxel rasterizer against closed forms: SVRaster's activation, a box of constant
// density, the front-to-back order of every sign octant, the alpha cap, skip and early stop.
#include <gtest/gtest.h>

#include <cmath>

#include "voxel/antialias_downsample.hpp"
#include "voxel/ray_order.hpp"
#include "voxel/voxel_rasterizer.hpp"
#include "voxel_test_scenes.hpp"

namespace lfd::voxel {
namespace {

using testing::add_voxel;
using testing::camera_through;
using testing::empty_scene;
using testing::raw_density_for;

float centre_transmittance(const render::RasterImage& img) {
  return img.transmittance[size_t(img.height / 2) * size_t(img.width) + size_t(img.width / 2)];
}
glm::vec3 centre_rgb(const render::RasterImage& img) {
  const size_t p = (size_t(img.height / 2) * size_t(img.width) + size_t(img.width / 2)) * 3;
  return {img.rgb[p], img.rgb[p + 1], img.rgb[p + 2]};
}

TEST(ExpLinear11, IsLinearAbove1p1AndExponentialBelowMeetingAt1p1) {
  EXPECT_FLOAT_EQ(scene::exp_linear_11(2.0f), 2.0f);
  EXPECT_NEAR(scene::exp_linear_11(0.0f), 1.1f * std::exp(-1.0f), 1e-6f);
  EXPECT_NEAR(scene::exp_linear_11(1.1f - 1e-4f), 1.1f, 2e-4f);
  EXPECT_NEAR(scene::exp_linear_11(-5.0f), std::exp(-5.0f / 1.1f - 1.0f + std::log(1.1f)), 1e-7f);
}

TEST(Trilinear, CornerBitsAreXYZAndTheCentreIsTheMean) {
  std::array<float, 8> c{};
  for (int i = 0; i < 8; ++i) c[size_t(i)] = float(i);
  EXPECT_FLOAT_EQ(scene::trilinear(c, {1, 0, 0}), 4.0f);
  EXPECT_FLOAT_EQ(scene::trilinear(c, {0, 1, 0}), 2.0f);
  EXPECT_FLOAT_EQ(scene::trilinear(c, {0, 0, 1}), 1.0f);
  EXPECT_FLOAT_EQ(scene::trilinear(c, {0.5f, 0.5f, 0.5f}), 3.5f);
}

TEST(VoxelRasterizer, ABoxOfConstantDensityTransmitsExpOfMinus100SigmaChord) {
  scene::VoxelScene s = empty_scene();
  const float sigma = 0.04f;  // below 1.1: the exponential branch of the activation
  add_voxel(s, {1, 1, 1}, 2, raw_density_for(sigma), {1, 1, 1});  // edge 0.25: tau = 1
  const glm::vec3 centre = s.voxel_center(0);
  const float edge = s.voxel_size(0);
  // Straight through the faces: chord = edge.
  const auto img = rasterize_voxels(s, camera_through(centre - glm::vec3(0, 0, 2), centre));
  EXPECT_NEAR(centre_transmittance(img), std::exp(-100.0f * sigma * edge), 1e-5f);
  // Along a face diagonal from edge to edge: chord = edge sqrt(2).
  const glm::vec3 diagonal = glm::normalize(glm::vec3(1, 0, 1));
  const float alpha = voxel_alpha(s, 0, centre - 2.0f * diagonal, diagonal);
  EXPECT_NEAR(1.0f - alpha, std::exp(-100.0f * sigma * edge * std::sqrt(2.0f)), 1e-5f);
  // K samples of a constant density integrate it exactly too.
  s.samples_per_voxel = 4;
  EXPECT_NEAR(centre_transmittance(rasterize_voxels(s, camera_through(centre - glm::vec3(0, 0, 2), centre))),
              std::exp(-100.0f * sigma * edge), 1e-5f);
}

TEST(VoxelRasterizer, DegreeZeroColourIsShPlusHalfAndTheBackgroundFillsTheRest) {
  scene::VoxelScene s = empty_scene();
  add_voxel(s, {0, 0, 0}, 0, raw_density_for(0.05f), {0.2f, 0.6f, 0.9f});  // the root cell
  const glm::vec3 bg(0.1f, 0.3f, 0.5f);
  VoxelRenderSettings settings;
  settings.background = bg;
  const auto img = rasterize_voxels(s, camera_through({0, 0, -3}, {0, 0, 0}), settings);
  const float t = std::exp(-100.0f * 0.05f * 1.0f);
  const glm::vec3 expected = (1.0f - t) * glm::vec3(0.2f, 0.6f, 0.9f) + t * bg;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre_rgb(img)[c], expected[c], 1e-5f);
}

TEST(VoxelRasterizer, AlphaIsCappedAt0p99999) {
  scene::VoxelScene s = empty_scene();
  add_voxel(s, {0, 0, 0}, 0, 50.0f, {1, 0, 0});  // tau = 5000
  const auto img = rasterize_voxels(s, camera_through({0, 0, -3}, {0, 0, 0}));
  EXPECT_NEAR(centre_transmittance(img), 1e-5f, 1e-7f);  // 0.99999f is one float step off
}

TEST(VoxelRasterizer, VoxelsBelowAlpha1eMinus5AreSkipped) {
  scene::VoxelScene s = empty_scene();
  // sigma such that 1 - exp(-100 sigma) is 0.5e-5: composited, it would leave T = 1 - 0.5e-5.
  add_voxel(s, {0, 0, 0}, 0, raw_density_for(0.5e-7f), {1, 1, 1});
  const auto img = rasterize_voxels(s, camera_through({0, 0, -3}, {0, 0, 0}));
  EXPECT_EQ(centre_transmittance(img), 1.0f);
  EXPECT_EQ(centre_rgb(img), glm::vec3(0.0f));
}

TEST(VoxelRasterizer, TheRayStopsOnceTransmittanceFallsBelow1eMinus4) {
  scene::VoxelScene s = empty_scene();
  const float edge = 0.5f;  // level 1
  const float front_t = 9e-5f;
  add_voxel(s, {0, 0, 0}, 1, raw_density_for(-std::log(front_t) / (100.0f * edge)), {1, 0, 0});
  add_voxel(s, {0, 0, 1}, 1, 50.0f, {0, 1, 0});  // behind it along +z, opaque
  const glm::vec3 through = s.voxel_center(0);
  const auto img = rasterize_voxels(s, camera_through(through - glm::vec3(0, 0, 3), through));
  EXPECT_NEAR(centre_transmittance(img), front_t, 1e-6f);  // not ~1e-9: the back voxel never came
  EXPECT_EQ(centre_rgb(img).g, 0.0f);
}

TEST(RayOrder, FrontVoxelOccludesTheBackOneFromEveryOctant) {
  // The 8 children of the root, opaque, each its own colour; looking along each octant's
  // diagonal through the nearest child's centre, that child must be what the pixel shows.
  for (int octant = 0; octant < 8; ++octant) {
    scene::VoxelScene s = empty_scene();
    for (uint32_t child = 0; child < 8; ++child)
      add_voxel(s, {child >> 2 & 1u, child >> 1 & 1u, child & 1u}, 1, 50.0f,
                {float(child >> 2 & 1u), float(child >> 1 & 1u), float(child & 1u)});
    const glm::vec3 d = glm::normalize(glm::vec3(octant & 4 ? -1 : 1, octant & 2 ? -1 : 1, octant & 1 ? -1 : 1));
    ASSERT_EQ(direction_octant(d), octant);
    // The nearest child sits on the side the ray comes from: index bit set where d < 0.
    const uint32_t near = uint32_t(octant);
    const glm::vec3 near_centre = s.voxel_center(near);
    const auto img = rasterize_voxels(s, camera_through(near_centre - 3.0f * d, near_centre));
    const glm::vec3 expected(float(near >> 2 & 1u), float(near >> 1 & 1u), float(near & 1u));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre_rgb(img)[c], expected[c], 0.01f) << "octant " << octant;
  }
}

TEST(RayOrder, CoarseAndFineLeavesSortFrontToBackAlongEachAxis) {
  // A level-1 leaf at x low and two level-2 leaves at x high: for a ray going +x the coarse one
  // comes first, for -x last.
  scene::VoxelScene s = empty_scene();
  add_voxel(s, {0, 0, 0}, 1, 0.0f, {1, 1, 1});
  add_voxel(s, {2, 0, 0}, 2, 0.0f, {1, 1, 1});
  add_voxel(s, {3, 0, 0}, 2, 0.0f, {1, 1, 1});
  const RayOrder order(s);
  EXPECT_LT(order.key(0, 0), order.key(1, 0));
  EXPECT_LT(order.key(1, 0), order.key(2, 0));
  EXPECT_GT(order.key(0, 4), order.key(1, 4));
  EXPECT_GT(order.key(1, 4), order.key(2, 4));
}

TEST(VoxelRasterizer, SupersamplingKeepsAUniformImageUniform) {
  scene::VoxelScene s = empty_scene();
  add_voxel(s, {0, 0, 0}, 0, 50.0f, {0.3f, 0.6f, 0.9f});
  VoxelRenderSettings settings;
  settings.supersampling = 1.5f;
  const auto img = rasterize_voxels(s, camera_through({0, 0, -1.2f}, {0, 0, 0}, 20), settings);
  ASSERT_EQ(img.width, 20);
  for (size_t p = 0; p < img.transmittance.size(); ++p) ASSERT_NEAR(img.rgb[p * 3 + 1], 0.6f * 0.99999f, 1e-4f);
}

TEST(AntialiasDownsample, AveragesPairsAtHalfSizeAndKeepsTheMean) {
  std::vector<float> in{0, 1, 0, 1, 0, 1, 0, 1};  // 8x1, one channel
  const auto out = antialias_downsample(in, 8, 1, 1, 4, 1);
  ASSERT_EQ(out.size(), 4u);
  float sum = 0;
  for (float v : out) sum += v;
  EXPECT_NEAR(sum / 4, 0.5f, 0.05f);
  for (size_t i = 1; i + 1 < out.size(); ++i) EXPECT_NEAR(out[i], 0.5f, 1e-6f);
}

}  // namespace
}  // namespace lfd::voxel
