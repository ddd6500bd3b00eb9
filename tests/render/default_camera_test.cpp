// The default camera frames the content: kFramedOpacity of the content's opacity projects inside
// the view shrunk by kFrameMargin, and no more when the camera comes 10% closer (the content
// fills the frame); the focal plane passes through the content's centre; haze does not move it.
#include <gtest/gtest.h>

#include <random>

#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "scene/scene_bounds.hpp"
#include "render/scene_generator.hpp"
#include "tests/render/render_test_scenes.hpp"

namespace lfd::render {
namespace {

scene::GaussianScene box_of_gaussians(size_t n, float opacity, std::array<float, 3> lo,
                               std::array<float, 3> hi, uint32_t seed) {
  scene::GaussianScene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (size_t i = 0; i < n; ++i) {
    std::array<float, 3> p;
    for (int a = 0; a < 3; ++a) p[a] = lo[a] + (hi[a] - lo[a]) * u(rng);
    testing::add_gaussian(s, p, {0.02f, 0.02f, 0.02f}, opacity, {u(rng), u(rng), u(rng)});
  }
  return s;
}

// The opacity-weighted share of the content (opacity >= kContentMinOpacity) that `camera`
// shows inside its view shrunk by `margin` on every side.
double share_inside(const Camera& camera, const scene::GaussianScene& s, float margin) {
  double inside = 0, total = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s.opacities[i] < kContentMinOpacity) continue;
    const glm::vec3 c = camera.to_camera(glm::vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]));
    total += s.opacities[i];
    if (c.z > 0 && std::fabs(c.x / (c.z * camera.tan_half_fov_x())) <= 1 - margin &&
        std::fabs(c.y / (c.z * camera.tan_half_fov_y())) <= 1 - margin)
      inside += s.opacities[i];
  }
  return inside / total;
}

TEST(DefaultCamera, ContentFillsTheViewInsideTheMargin) {
  const scene::GaussianScene s = box_of_gaussians(4000, 0.8f, {-2, -1, 4}, {3, 0.5f, 6}, 1);
  for (float aspect : {0.75f, 1.0f, 16.0f / 9.0f})
    for (float orbit : {0.0f, 35.0f}) {
      const CameraSpec spec = frame_scene(s, kDefaultFovYDeg, orbit, aspect);
      const int w = int(std::lround(400 * aspect));
      EXPECT_GE(share_inside(camera_from_spec(spec, w, 400), s, kFrameMargin), kFramedOpacity - 0.002)
          << aspect << " " << orbit;
      // Tight: 10% closer, a visible part of the content would leave the margin.
      CameraSpec closer = spec;
      closer.position = spec.look_at + 0.9f * (spec.position - spec.look_at);
      EXPECT_LT(share_inside(camera_from_spec(closer, w, 400), s, kFrameMargin), kFramedOpacity - 0.01)
          << aspect << " " << orbit;
      // The focal plane passes through the centre of the content's box; y down: seen from above.
      const auto c = scene::content_bounds(s).center();
      EXPECT_NEAR(glm::length(spec.look_at - glm::vec3(c[0], c[1], c[2])), 0.0f, 1e-5f);
      EXPECT_GT(spec.look_at.y, spec.position.y);
    }
}

TEST(DefaultCamera, FaintHazeAndFarFloatersDoNotMoveTheFrame) {
  const scene::GaussianScene content = box_of_gaussians(4000, 0.8f, {-1, -1, 4}, {1, 1, 6}, 2);
  scene::GaussianScene hazy = content;
  const scene::GaussianScene haze = box_of_gaussians(2000, 0.05f, {-40, -40, -40}, {40, 40, 40}, 3);
  const scene::GaussianScene floaters = box_of_gaussians(40, 0.9f, {30, 30, 30}, {35, 35, 35}, 4);
  for (const scene::GaussianScene* extra : {&haze, &floaters})
    for (size_t i = 0; i < extra->size(); ++i)
      testing::add_gaussian(hazy, extra->positions[i], extra->scales[i], extra->opacities[i],
                            {0.5f, 0.5f, 0.5f});
  const CameraSpec a = frame_scene(content), b = frame_scene(hazy);
  EXPECT_LT(glm::length(a.look_at - b.look_at), 0.05f);
  EXPECT_NEAR(glm::length(a.position - a.look_at), glm::length(b.position - b.look_at), 0.15f);
}

TEST(DefaultCamera, ContentBoundsWeighByOpacity) {
  // Half the Gaussians, nearly transparent, spread wide: the weighted box follows the opaque half.
  scene::GaussianScene s = box_of_gaussians(1000, 0.9f, {0, 0, 0}, {1, 1, 1}, 5);
  const scene::GaussianScene faint = box_of_gaussians(1000, 0.12f, {-10, -10, -10}, {10, 10, 10}, 6);
  for (size_t i = 0; i < faint.size(); ++i)
    testing::add_gaussian(s, faint.positions[i], faint.scales[i], faint.opacities[i], {0, 0, 0});
  const scene::SceneBounds weighted = scene::content_bounds(s), plain = scene::robust_bounds(s, 0.05, 0.95);
  for (int a = 0; a < 3; ++a) {
    EXPECT_GT(weighted.min[a], -3.0f);
    EXPECT_LT(weighted.max[a], 4.0f);
    EXPECT_LT(plain.min[a], -5.0f);  // the unweighted box is decided by the faint half
  }
}

}  // namespace
}  // namespace lfd::render
