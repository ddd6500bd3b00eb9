// The fixtures (tests/data/scenes): the same 3 real Gaussians as standard PLY, .splat and SPZ v3 agree to
// each format's precision (docs/rendering.md "What each reader follows"), and the real PlayCanvas
// compressed PLY (optional, ../shared/data) loads completely.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "scene/gaussian_io.hpp"
#include "scene/sh_basis.hpp"
#include "tests/test_data.hpp"

namespace lfd::scene {
namespace {

const std::filesystem::path kScenes = test::fixtures() / "scenes";

float rgb_of(const scene::GaussianScene& s, size_t i, int ch) { return scene::sh_dc_to_color(s.sh_of(i)[ch]); }

// Quaternions q and -q are the same rotation.
float quaternion_distance(const std::array<float, 4>& a, const std::array<float, 4>& b) {
  float plus = 0, minus = 0;
  for (int k = 0; k < 4; ++k) {
    plus = std::max(plus, std::fabs(a[k] - b[k]));
    minus = std::max(minus, std::fabs(a[k] + b[k]));
  }
  return std::min(plus, minus);
}

TEST(SceneFormats, ThreePointsPlyMatchesTheReferenceTable) {
  const scene::GaussianScene s = scene::load_gaussian_scene(kScenes / "three-points.ply");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s.sh_degree, 3);
  // The file's values activated by hand (rgb = 0.5 + C0 f_dc, opacity = sigmoid, scale = exp;
  // docs/rendering.md "Stored parameters"), rounded to the digits shown.
  EXPECT_NEAR(s.positions[0][0], 2.00785f, 1e-4);
  EXPECT_NEAR(s.positions[2][1], -1.01235f, 1e-4);
  EXPECT_NEAR(rgb_of(s, 0, 0), 0.8125f, 1e-3);
  EXPECT_NEAR(rgb_of(s, 2, 1), 0.6238f, 1e-3);
  EXPECT_NEAR(s.opacities[1], 0.0388f, 1e-3);
  EXPECT_NEAR(s.scales[2][2], 0.04220f, 1e-4);
  // Raw (1.0344, -0.1992, -0.1048, -0.0145) has length 1.0587 and must be normalised.
  EXPECT_NEAR(s.rotations[0][0], 1.0344f / 1.0587f, 1e-3);
  EXPECT_NEAR(s.rotations[0][1], -0.1992f / 1.0587f, 1e-3);
  for (size_t i = 0; i < 3; ++i) {
    const auto& q = s.rotations[i];
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0f, 1e-5);
  }
}

TEST(SceneFormats, SplatAgreesWithPlyToEightBits) {
  const scene::GaussianScene ply = scene::load_gaussian_scene(kScenes / "three-points.ply");
  const scene::GaussianScene splat = scene::load_gaussian_scene(kScenes / "three-points.splat");
  ASSERT_EQ(splat.size(), 3u);
  EXPECT_EQ(splat.sh_degree, 0);
  for (size_t i = 0; i < 3; ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(splat.positions[i][a], ply.positions[i][a], 1e-5);
      EXPECT_NEAR(splat.scales[i][a], ply.scales[i][a], 1e-5 * ply.scales[i][a] + 1e-7);
      // ±1 LSB: the fixture is neither consistently rounded nor truncated (docs/rendering.md).
      EXPECT_NEAR(rgb_of(splat, i, a), std::clamp(rgb_of(ply, i, a), 0.0f, 1.0f), 1.01f / 255);
    }
    EXPECT_NEAR(splat.opacities[i], ply.opacities[i], 1.01f / 255);
    EXPECT_LT(quaternion_distance(splat.rotations[i], ply.rotations[i]), 0.02f);
  }
}

TEST(SceneFormats, SpzAgreesWithPlyToItsQuantisation) {
  const scene::GaussianScene ply = scene::load_gaussian_scene(kScenes / "three-points.ply");
  const scene::GaussianScene spz = scene::load_gaussian_scene(kScenes / "three-points.spz");
  ASSERT_EQ(spz.size(), 3u);
  ASSERT_EQ(spz.sh_degree, 3);
  for (size_t i = 0; i < 3; ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(spz.positions[i][a], ply.positions[i][a], 0.6f / 4096);  // 12 fraction bits
      // log scale in steps of 1/16
      EXPECT_NEAR(std::log(spz.scales[i][a]), std::log(ply.scales[i][a]), 0.5f / 16 + 1e-4);
      // f_dc in steps of 1 / (0.15 * 255), clamped to the byte range
      const float f_dc = std::clamp(ply.sh_of(i)[a], -0.5f / 0.15f, 0.5f / 0.15f);
      EXPECT_NEAR(spz.sh_of(i)[a], f_dc, 0.6f / (0.15f * 255));
    }
    EXPECT_NEAR(spz.opacities[i], ply.opacities[i], 0.6f / 255);
    EXPECT_LT(quaternion_distance(spz.rotations[i], ply.rotations[i]), 0.004f);
    // SH rest: (b - 128) / 128, degree 1 in 5-bit and higher degrees in 4-bit buckets.
    for (int k = 3; k < 16 * 3; ++k) {
      const float expected = std::clamp(ply.sh_of(i)[k], -1.0f, 127.0f / 128);
      const float tolerance = k < 4 * 3 ? 4.5f / 128 : 8.5f / 128;
      EXPECT_NEAR(spz.sh_of(i)[k], expected, tolerance) << "Gaussian " << i << " value " << k;
    }
  }
}

TEST(SceneFormats, GuitarCompressedPlyLoadsEveryGaussianFinite) {
  LFD_REQUIRE_SHARED_FILE("scenes/guitar.compressed.ply");
  const scene::GaussianScene s = scene::load_gaussian_scene(test::shared_data() / "scenes/guitar.compressed.ply");
  ASSERT_EQ(s.size(), 90854u);
  EXPECT_EQ(s.sh_degree, 0);
  for (size_t i = 0; i < s.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      ASSERT_TRUE(std::isfinite(s.positions[i][a]));
      ASSERT_GT(s.scales[i][a], 0.0f);
    }
    ASSERT_GE(s.opacities[i], 0.0f);
    ASSERT_LE(s.opacities[i], 1.0f);
  }
}

}  // namespace
}  // namespace lfd::scene
