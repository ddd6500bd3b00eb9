// The procedural generator: deterministic per seed, exact counts, valid values, and a depth
// structure with several distinct layers (ground, objects in rows, far background).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/scene_bounds.hpp"
#include "render/scene_generator.hpp"
#include "util/error.hpp"

namespace lfd::render {
namespace {

TEST(SceneGenerator, SameSeedGivesTheSameScene) {
  for (const auto& kind : generator_kinds()) {
    const scene::GaussianScene a = generate_scene({kind, 40000, 7, 1});
    const scene::GaussianScene b = generate_scene({kind, 40000, 7, 1});
    EXPECT_EQ(a.positions, b.positions) << kind;
    EXPECT_EQ(a.rotations, b.rotations) << kind;
    EXPECT_EQ(a.sh, b.sh) << kind;
  }
}

TEST(SceneGenerator, DifferentSeedsGiveDifferentScenes) {
  const scene::GaussianScene a = generate_scene({"tabletop", 1000, 1, 1});
  const scene::GaussianScene b = generate_scene({"tabletop", 1000, 2, 1});
  EXPECT_NE(a.positions, b.positions);
}

TEST(SceneGenerator, ProducesExactlyTheRequestedCountAndDegree) {
  for (size_t count : {1u, 7u, 1000u, 123457u})
    for (int degree = 0; degree <= 3; ++degree) {
      const scene::GaussianScene s = generate_scene({"corridor", count, 3, degree});
      ASSERT_EQ(s.size(), count);
      ASSERT_EQ(s.sh_degree, degree);
      ASSERT_EQ(s.sh.size(), count * size_t(s.sh_coeffs()) * 3);
    }
}

TEST(SceneGenerator, ValuesAreValidActivatedGaussians) {
  const scene::GaussianScene s = generate_scene({"tabletop", 20000, 11, 2});
  for (size_t i = 0; i < s.size(); ++i) {
    const auto& q = s.rotations[i];
    ASSERT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0f, 1e-4);
    for (float v : s.scales[i]) ASSERT_GT(v, 0.0f);
    ASSERT_GT(s.opacities[i], 0.0f);
    ASSERT_LT(s.opacities[i], 1.0f);
    // Surfaces: the thinnest axis is much thinner than the widest.
    const auto [lo, hi] = std::minmax({s.scales[i][0], s.scales[i][1], s.scales[i][2]});
    ASSERT_LT(lo, 0.5f * hi);
  }
}

TEST(SceneGenerator, HasViewDependentColour) {
  const scene::GaussianScene s = generate_scene({"tabletop", 5000, 1, 1});
  double energy = 0;
  for (size_t i = 0; i < s.size(); ++i)
    for (int k = 3; k < 12; ++k) energy += std::fabs(s.sh_of(i)[k]);
  EXPECT_GT(energy / double(s.size() * 9), 0.02);
}

// Counts runs of occupied 0.25-unit depth bins along z among the Gaussians standing above the
// ground (below the dome, between the walls): separate object rows leave gaps between runs.
int depth_layers(const scene::GaussianScene& s, float max_abs_x, float max_abs_z) {
  std::set<int> bins;
  for (const auto& p : s.positions)
    if (p[1] < 0.95f && p[1] > -1.5f && std::fabs(p[0]) < max_abs_x && std::fabs(p[2]) < max_abs_z)
      bins.insert(int(std::floor(p[2] / 0.25f)));
  int layers = 0, previous = -1000000;
  for (int b : bins) {
    if (b != previous + 1) ++layers;
    previous = b;
  }
  return layers;
}

TEST(SceneGenerator, TabletopHasObjectsAtSeveralDepthsAndAFarBackground) {
  const scene::GaussianScene s = generate_scene({"tabletop", 100000, 1, 1});
  EXPECT_GE(depth_layers(s, 4.0f, 4.0f), 3);
  // Ground: a large share of Gaussians lies flat on y = +1 (y down, as in trained scenes).
  const auto on_ground = std::count_if(s.positions.begin(), s.positions.end(),
                                       [](const auto& p) { return std::fabs(p[1] - 1) < 1e-3f; });
  EXPECT_GT(on_ground, 10000);
  // Background: some Gaussians far away (> 8 units), most within a few units.
  const auto far = std::count_if(s.positions.begin(), s.positions.end(), [](const auto& p) {
    return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) > 8;
  });
  EXPECT_GT(far, 1000);
  EXPECT_LT(far, 5000);
  // The default framing box follows the ground and objects, not the backdrop.
  const scene::SceneBounds b = scene::robust_bounds(s);
  EXPECT_LT(b.radius(), 8.0f);
  EXPECT_GT(b.radius(), 3.0f);
}

TEST(SceneGenerator, CorridorRecedesInDepth) {
  const scene::GaussianScene s = generate_scene({"corridor", 100000, 1, 1});
  EXPECT_GE(depth_layers(s, 1.2f, 11.0f), 3);  // objects along it; walls excluded
  const scene::SceneBounds b = scene::exact_bounds(s);
  EXPECT_GT(b.max[2], 11.0f);  // end wall far away along +z, the viewing direction
  EXPECT_LT(b.min[2], -2.0f);
  EXPECT_LT(b.max[0] - b.min[0], 3.5f);  // narrow
}

TEST(SceneGenerator, RejectsUnknownKindAndAbsurdCounts) {
  EXPECT_THROW(generate_scene({"nebula", 10, 1, 1}), InputError);
  EXPECT_THROW(generate_scene({"tabletop", 0, 1, 1}), InputError);
  EXPECT_THROW(generate_scene({"tabletop", size_t(1) << 40, 1, 1}), InputError);
  EXPECT_THROW(generate_scene({"tabletop", 10, 1, 4}), InputError);
}

TEST(SceneBounds, IgnoresFarOutliers) {
  scene::GaussianScene s = generate_scene({"tabletop", 10000, 1, 0});
  s.positions[0] = {1e6f, 1e6f, 1e6f};
  const scene::SceneBounds robust = scene::robust_bounds(s);
  EXPECT_LT(robust.max[0], 20.0f);
  EXPECT_GT(scene::exact_bounds(s).max[0], 1e5f);
}

}  // namespace
}  // namespace lfd::render
