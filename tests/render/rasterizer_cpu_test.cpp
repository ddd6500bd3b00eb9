// Analytic cases for the reference rasterizer (docs/rendering.md "The CPU reference rasterizer").
#include <cmath>

#include <gtest/gtest.h>

#include "render/rasterizer_cpu.hpp"
#include "render/spherical_harmonics.hpp"
#include "render_test_scenes.hpp"

namespace lfd::render {
namespace {

using testing::add_gaussian;

// Camera at the origin looking down +z (y down in the image is world -y).
Camera axis_camera(int w, int h, float fov_y = 0.6f) {
  return make_look_at_camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, fov_y, w, h);
}

// World position that projects to pixel (px, py) at depth z.
std::array<float, 3> at_pixel(const Camera& c, float px, float py, float z) {
  const float x = (px - (c.width - 1) * 0.5f) * z / c.focal_x_px();
  const float y = (py - (c.height - 1) * 0.5f) * z / c.focal_y_px();
  const glm::vec3 w = c.position_world + z * c.forward() + x * c.right() + y * c.down();
  return {w.x, w.y, w.z};
}

// A disk facing the camera (zero z scale) has the exact screen variance (f s / z)^2 + 0.3.
float disk_scale_for_variance(const Camera& c, float variance_px2, float z) {
  return std::sqrt(variance_px2 - 0.3f) * z / c.focal_x_px();
}

TEST(Rasterizer, IsotropicGaussianCentreAndFalloffAreAnalytic) {
  const Camera cam = axis_camera(33, 33);
  scene::GaussianScene s;
  const float z = 3.0f, var = 6.0f, o = 0.8f;
  const float sc = disk_scale_for_variance(cam, var, z);
  add_gaussian(s, at_pixel(cam, 16, 16, z), {sc, sc, 0.0f}, o, {0.9f, 0.4f, 0.1f});
  RasterSettings rs;
  rs.background = {0.0f, 0.0f, 1.0f};
  const RasterImage img = rasterize(s, cam, rs);
  const auto rgb = [&](int x, int y, int c) { return img.rgb[(size_t(y) * 33 + x) * 3 + c]; };
  // Centre: alpha = o; out = c o + (1 - o) bg.
  EXPECT_NEAR(rgb(16, 16, 0), 0.9f * o, 1e-5f);
  EXPECT_NEAR(rgb(16, 16, 2), 0.1f * o + (1.0f - o), 1e-5f);
  EXPECT_NEAR(img.transmittance[16 * 33 + 16], 1.0f - o, 1e-5f);
  for (int d : {1, 3, 5}) {
    const float alpha = o * std::exp(-0.5f * d * d / var);
    EXPECT_NEAR(rgb(16 + d, 16, 0), 0.9f * alpha, 1e-5f) << d;
    EXPECT_NEAR(rgb(16, 16 - d, 1), 0.4f * alpha, 1e-5f) << d;
  }
  // Far corner: untouched background.
  EXPECT_FLOAT_EQ(rgb(0, 0, 2), 1.0f);
  EXPECT_FLOAT_EQ(rgb(0, 0, 0), 0.0f);
}

TEST(Rasterizer, NearCullDropsGaussiansAtOrBefore0_2) {
  const Camera cam = axis_camera(16, 16);
  scene::GaussianScene s;
  add_gaussian(s, {0.0f, 0.0f, 0.19f}, {0.05f, 0.05f, 0.05f}, 0.9f, {1, 1, 1});
  const auto proj = preprocess(s, cam, {});
  EXPECT_EQ(proj[0].radius_px, 0);
  const RasterImage img = rasterize(s, cam);
  for (float t : img.transmittance) EXPECT_FLOAT_EQ(t, 1.0f);
}

TEST(Rasterizer, BlendsFrontToBackAndStopsBeforeTransmittanceFallsBelow1e4) {
  const Camera cam = axis_camera(17, 17);
  scene::GaussianScene s;
  const float sc = disk_scale_for_variance(cam, 50.0f, 1.0f);
  // Listed back to front on purpose; depths 4, 3, 2, 1.
  add_gaussian(s, at_pixel(cam, 8, 8, 4.0f), {4 * sc, 4 * sc, 0}, 0.5f, {0, 0, 1});
  add_gaussian(s, at_pixel(cam, 8, 8, 3.0f), {3 * sc, 3 * sc, 0}, 0.95f, {0, 1, 0});
  add_gaussian(s, at_pixel(cam, 8, 8, 2.0f), {2 * sc, 2 * sc, 0}, 0.99f, {1, 0, 0});
  add_gaussian(s, at_pixel(cam, 8, 8, 1.0f), {sc, sc, 0}, 0.9f, {0.5f, 0.5f, 0.5f});
  RasterSettings rs;
  rs.background = {1, 1, 1};
  const RasterImage img = rasterize(s, cam, rs);
  const size_t p = 8 * 17 + 8;
  // T: 1 -> 0.1 (alpha 0.9) -> 0.001 (0.99) -> 5e-5 < 1e-4: the third is not blended, nor the fourth.
  EXPECT_NEAR(img.rgb[3 * p + 0], 0.5f * 0.9f + 1.0f * 0.99f * 0.1f + 0.001f, 1e-5f);
  EXPECT_NEAR(img.rgb[3 * p + 1], 0.5f * 0.9f + 0.001f, 1e-5f);
  EXPECT_NEAR(img.rgb[3 * p + 2], 0.5f * 0.9f + 0.001f, 1e-5f);
  EXPECT_NEAR(img.transmittance[p], 0.001f, 1e-6f);
}

TEST(Rasterizer, AlphaIsCappedAt0_99) {
  const Camera cam = axis_camera(9, 9);
  scene::GaussianScene s;
  add_gaussian(s, at_pixel(cam, 4, 4, 2.0f), {0.05f, 0.05f, 0.0f}, 1.0f, {1, 1, 1});
  const RasterImage img = rasterize(s, cam);
  EXPECT_NEAR(img.transmittance[4 * 9 + 4], 0.01f, 1e-6f);
}

TEST(Rasterizer, FootprintIsTheTileRectangleOfTheRadius) {
  // Variance 3.5 px^2: radius = ceil(3 sqrt(3.5 + sqrt(0.1))) = 6. Centred on column 10 the
  // tile rectangle ends at column 15 although alpha at column 16 (6 px, 0.99 e^{-36/7} = 0.0058)
  // exceeds 1/255: the reference leaves it untouched (getRect).
  const Camera cam = axis_camera(48, 16);
  scene::GaussianScene s;
  const float z = 2.0f;
  const float sc = disk_scale_for_variance(cam, 3.5f, z);
  add_gaussian(s, at_pixel(cam, 10, 8, z), {sc, sc, 0.0f}, 0.99f, {1, 1, 1});
  const auto proj = preprocess(s, cam, {});
  ASSERT_EQ(proj[0].radius_px, 6);
  EXPECT_EQ(proj[0].rect_max.x, 1);
  const RasterImage img = rasterize(s, cam);
  const auto alpha_at = [&](int x) { return 1.0f - img.transmittance[size_t(8) * 48 + x]; };
  EXPECT_NEAR(alpha_at(15), 0.99f * std::exp(-0.5f * 25.0f / 3.5f), 1e-5f);
  EXPECT_FLOAT_EQ(alpha_at(16), 0.0f);

  // Centred on column 15 (last of tile 0) the rectangle covers tile 1 too, analytically.
  scene::GaussianScene s2;
  add_gaussian(s2, at_pixel(cam, 15, 8, z), {sc, sc, 0.0f}, 0.99f, {1, 1, 1});
  const RasterImage img2 = rasterize(s2, cam);
  for (int x : {16, 18, 20})
    EXPECT_NEAR(1.0f - img2.transmittance[size_t(8) * 48 + x],
                0.99f * std::exp(-0.5f * float((x - 15) * (x - 15)) / 3.5f), 1e-5f) << x;
}

TEST(Rasterizer, SkipsContributionsBelow1Over255) {
  const Camera cam = axis_camera(33, 1);
  scene::GaussianScene s;
  const float sc = disk_scale_for_variance(cam, 4.0f, 2.0f);
  add_gaussian(s, at_pixel(cam, 16, 0, 2.0f), {sc, sc, 0.0f}, 0.5f, {1, 1, 1});
  const RasterImage img = rasterize(s, cam);
  for (int d = 0; d <= 16; ++d) {
    const float a = 0.5f * std::exp(-0.5f * d * d / 4.0f);
    const float got = 1.0f - img.transmittance[size_t(16 + d)];
    if (a < 1.0f / 255.0f - 1e-6f) EXPECT_FLOAT_EQ(got, 0.0f) << d;
    else if (a > 1.0f / 255.0f + 1e-6f) EXPECT_NEAR(got, a, 1e-6f) << d;
  }
}

TEST(Rasterizer, OffAxisShiftMovesTheMeanByTheShiftInPixels) {
  Camera cam = axis_camera(32, 32);
  scene::GaussianScene s;
  add_gaussian(s, {0.0f, 0.0f, 3.0f}, {0.01f, 0.01f, 0.01f}, 0.9f, {1, 1, 1});
  cam.shift_x_ndc = 0.25f;
  const auto proj = preprocess(s, cam, {});
  EXPECT_NEAR(proj[0].mean_px.x, 15.5f + 0.25f * 16.0f, 1e-4f);
}

TEST(Rasterizer, SubsetRendersOnlyThoseGaussians) {
  const Camera cam = axis_camera(32, 32);
  scene::GaussianScene s;
  add_gaussian(s, at_pixel(cam, 8, 8, 2.0f), {0.02f, 0.02f, 0.0f}, 0.9f, {1, 0, 0});
  add_gaussian(s, at_pixel(cam, 24, 24, 2.0f), {0.02f, 0.02f, 0.0f}, 0.9f, {0, 1, 0});
  const std::vector<uint32_t> only_second{1};
  const RasterImage img = rasterize(s, cam, {}, only_second);
  EXPECT_FLOAT_EQ(img.transmittance[8 * 32 + 8], 1.0f);
  EXPECT_LT(img.transmittance[24 * 32 + 24], 0.2f);
}

TEST(Rasterizer, TileListsAreSortedByDepthWithTiesInSceneOrder) {
  const Camera cam = axis_camera(40, 24);
  scene::GaussianScene s;
  for (int i = 0; i < 6; ++i)
    add_gaussian(s, at_pixel(cam, 5.0f + 5.0f * i, 10.0f, i % 2 ? 2.0f : 3.0f), {0.03f, 0.03f, 0.03f}, 0.5f, {1, 1, 1});
  add_gaussian(s, at_pixel(cam, 20, 10, 2.0f), {0.03f, 0.03f, 0.03f}, 0.5f, {1, 1, 1});
  const auto proj = preprocess(s, cam, {});
  const TileBins bins = bin_and_sort(proj, cam.width, cam.height);
  ASSERT_EQ(bins.range_begin.size(), size_t(3 * 2 + 1));
  for (size_t t = 0; t + 1 < bins.range_begin.size(); ++t)
    for (uint32_t k = bins.range_begin[t]; k + 1 < bins.range_begin[t + 1]; ++k) {
      const auto a = bins.ids[k], b = bins.ids[k + 1];
      EXPECT_TRUE(proj[a].depth < proj[b].depth || (proj[a].depth == proj[b].depth && a < b));
    }
}

TEST(SphericalHarmonics, DegreeOneMatchesTheReferenceFormula) {
  float sh[12] = {0.1f, 0.2f, 0.3f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  const glm::vec3 c = eval_sh_color(1, sh, d);
  const float C0 = scene::kShC0, C1 = 0.4886025119029199f;
  EXPECT_NEAR(c.x, 0.5f + C0 * 0.1f - C1 * d.y, 1e-6f);
  EXPECT_NEAR(c.y, 0.5f + C0 * 0.2f + C1 * d.z, 1e-6f);
  EXPECT_NEAR(c.z, 0.5f + C0 * 0.3f - C1 * d.x, 1e-6f);
}

TEST(SphericalHarmonics, ClampsAtZeroOnlyAndIgnoresHigherBandsAtDegreeZero) {
  float sh[48] = {};
  sh[0] = -10.0f;  // red far below zero
  sh[1] = 10.0f;   // green far above one
  for (int i = 3; i < 48; ++i) sh[i] = 5.0f;
  const glm::vec3 c0 = eval_sh_color(0, sh, {0, 0, 1});
  EXPECT_FLOAT_EQ(c0.x, 0.0f);
  EXPECT_NEAR(c0.y, scene::sh_dc_to_color(10.0f), 1e-5f);
  const glm::vec3 c3 = eval_sh_color(3, sh, glm::normalize(glm::vec3(1, 2, 3)));
  EXPECT_NE(c3.z, c0.z);
}

}  // namespace
}  // namespace lfd::render
