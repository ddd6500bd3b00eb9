// Writers where users convert (`lfd scene convert`): every format read here, written as PLY,
// reads back exactly; written as SPZ v3, reads back within SPZ's quantisation steps (known
// truth: half a step per value), for the reference tools' files and for a real SOG.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "scene/gaussian_io.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::scene {
namespace {

namespace fs = std::filesystem;
const fs::path kFormats = test::fixtures() / "scenes" / "formats";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "lfd_scene_convert";
  fs::create_directories(dir);
  return dir / name;
}

class SceneConvert : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneConvert, PlyRoundTripIsExact) {
  const scene::GaussianScene s = scene::load_gaussian_scene(kFormats / GetParam());
  const fs::path out = scratch("exact.ply");
  scene::save_gaussian_scene(out, s);
  const scene::GaussianScene back = scene::load_gaussian_scene(out);
  ASSERT_EQ(back.size(), s.size());
  ASSERT_EQ(back.sh_degree, s.sh_degree);
  for (size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(back.positions[i], s.positions[i]);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(back.scales[i][a], s.scales[i][a], 1e-6f * s.scales[i][a]);
    EXPECT_NEAR(back.opacities[i], s.opacities[i], 1e-6f);
  }
  EXPECT_EQ(back.sh, s.sh);
}

TEST_P(SceneConvert, SpzRoundTripWithinItsQuantisation) {
  const scene::GaussianScene s = scene::load_gaussian_scene(kFormats / GetParam());
  const fs::path out = scratch("quantised.spz");
  scene::save_gaussian_scene(out, s);
  const scene::GaussianScene back = scene::load_gaussian_scene(out);
  ASSERT_EQ(back.size(), s.size());
  ASSERT_EQ(back.sh_degree, s.sh_degree);
  for (size_t i = 0; i < s.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(back.positions[i][a], s.positions[i][a], 0.5f / 4096 + 1e-6f);
      const float log_s = std::clamp(std::log(s.scales[i][a]), -10.0f, 255.0f / 16 - 10);
      EXPECT_NEAR(std::log(back.scales[i][a]), log_s, 0.5f / 16 + 1e-4f);
      const float dc = std::clamp(s.sh_of(i)[a], -0.5f / 0.15f, 0.5f / 0.15f);
      EXPECT_NEAR(back.sh_of(i)[a], dc, 0.5f / (0.15f * 255) + 1e-5f);
    }
    EXPECT_NEAR(back.opacities[i], s.opacities[i], 0.5f / 255 + 1e-6f);
    for (size_t k = 3; k < size_t(s.sh_coeffs()) * 3; ++k)
      EXPECT_NEAR(back.sh_of(i)[k], std::clamp(s.sh_of(i)[k], -1.0f, 127.0f / 128), 0.5f / 128 + 1e-5f);
    float dot = 0;
    for (int k = 0; k < 4; ++k) dot += back.rotations[i][k] * s.rotations[i][k];
    EXPECT_GT(std::fabs(dot), 0.999f);  // 9-bit smallest three
  }
}

INSTANTIATE_TEST_SUITE_P(ReferenceFiles, SceneConvert,
                         ::testing::Values("tabletop.ply", "tabletop.sog", "tabletop.glb",
                                           "tabletop-c1.ksplat"));

TEST(SceneConvertRealScene, BundledSogConvertsToSpzAndBack) {
  const scene::GaussianScene s = scene::load_gaussian_scene(test::project_data() / "scenes" / "playbot.sog");
  const fs::path out = scratch("playbot.spz");
  scene::save_gaussian_scene(out, s);
  const scene::GaussianScene back = scene::load_gaussian_scene(out);
  ASSERT_EQ(back.size(), s.size());
  for (size_t i = 0; i < s.size(); i += 97)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(back.positions[i][a], s.positions[i][a], 0.5f / 4096 + 1e-6f);
}

TEST(SceneConvertRealScene, UnknownOutputFormatWritesNothing) {
  const scene::GaussianScene s = scene::load_gaussian_scene(kFormats / "tabletop.ply");
  const fs::path out = scratch("scene.obj");
  fs::remove(out);
  EXPECT_THROW(scene::save_gaussian_scene(out, s), InputError);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace lfd::scene
