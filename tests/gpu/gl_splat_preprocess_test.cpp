// The GL preprocess pass against render::preprocess, Gaussian by Gaussian
// (gpu/splats/gl_splat_preprocess.hpp), on llvmpipe.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "../render/render_test_scenes.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/splats/gl_splat_preprocess.hpp"
#include "render/preprocess.hpp"
#include "render/quilt_geometry.hpp"
#include "render/scene_generator.hpp"

namespace lfd::gpu {
namespace {

struct GpuPreprocess {
  std::vector<SplatRecord> records;
  std::vector<uint32_t> keys, values;
  DrawArraysIndirect draw{};
};

GpuPreprocess run_gpu(const HeadlessContext& context, const scene::GaussianScene& scene,
                      const render::Camera& camera, const render::RasterSettings& settings) {
  GlScene gl_scene(scene, context.info());
  GlSplatPreprocess preprocess;
  SplatBuffers buffers;
  preprocess.run(gl_scene, camera, settings, buffers);
  GpuPreprocess out;
  out.records = buffers.records.download_as<SplatRecord>(scene.size());
  out.keys = buffers.keys.download_as<uint32_t>(scene.size());
  out.values = buffers.values.download_as<uint32_t>(scene.size());
  buffers.draw.download(&out.draw, sizeof(out.draw));
  return out;
}

float relative(float a, float b) { return std::abs(a - b) / std::max(1e-6f, std::max(std::abs(a), std::abs(b))); }

// A conic element's error against the conic's scale (its larger diagonal element): the
// off-diagonal element of a nearly axis-aligned footprint is close to 0, and measured against
// itself its last bits are all there is (an H200 gave 2.4e-4 of a small one).
float conic_error(const glm::vec4& gpu, const glm::vec3& cpu, int k) {
  const float scale = std::max({1e-6f, std::abs(cpu[0]), std::abs(cpu[2])});
  return std::abs(gpu[k] - cpu[k]) / scale;
}

// Every Gaussian: culled alike, same radius and tile rectangle (an integer from a float: one in
// a thousand may land on the other side of a rounding boundary, and then by one), mean, conic,
// depth and colour to float rounding; keys and values as documented; the visible count.
void expect_matches_cpu(const HeadlessContext& context, const scene::GaussianScene& scene,
                        const render::Camera& camera, const render::RasterSettings& settings) {
  const auto cpu = render::preprocess(scene, camera, settings);
  const GpuPreprocess gpu = run_gpu(context, scene, camera, settings);
  size_t visible = 0, integer_mismatches = 0;
  for (size_t i = 0; i < scene.size(); ++i) {
    const render::ProjectedGaussian& c = cpu[i];
    const SplatRecord& g = gpu.records[i];
    ASSERT_EQ(gpu.values[i], i);
    const float radius_px = g.conic_radius.w;
    const bool gpu_visible = radius_px > 0.0f;
    if ((c.radius_px > 0) != gpu_visible) {
      ++integer_mismatches;
      continue;
    }
    if (!gpu_visible) {
      ASSERT_EQ(gpu.keys[i], 0xFFFFFFFFu) << i;
      continue;
    }
    ++visible;
    uint32_t depth_bits;
    std::memcpy(&depth_bits, &g.mean_depth_opacity.z, 4);
    ASSERT_EQ(gpu.keys[i], depth_bits) << i;
    if (int(radius_px) != c.radius_px || g.rect.x != c.rect_min.x || g.rect.y != c.rect_min.y ||
        g.rect.z != c.rect_max.x || g.rect.w != c.rect_max.y) {
      ++integer_mismatches;
      EXPECT_LE(std::abs(int(radius_px) - c.radius_px), 1) << i;
    }
    EXPECT_NEAR(g.mean_depth_opacity.x, c.mean_px.x, 2e-3f) << i;
    EXPECT_NEAR(g.mean_depth_opacity.y, c.mean_px.y, 2e-3f) << i;
    EXPECT_LT(relative(g.mean_depth_opacity.z, c.depth), 1e-6f) << i;
    EXPECT_EQ(g.mean_depth_opacity.w, c.opacity) << i;
    for (int k = 0; k < 3; ++k) {
      EXPECT_LT(conic_error(g.conic_radius, c.conic, k), 2e-4f) << i << " conic " << k;
      EXPECT_NEAR(g.color[k], c.color[k], 2e-5f) << i << " colour " << k;
    }
  }
  std::printf("[ preprocess ] %zu Gaussians, %zu visible, %zu differ in radius or rectangle\n", scene.size(),
              visible, integer_mismatches);
  EXPECT_LE(integer_mismatches, scene.size() / 1000) << "radius or rectangle differs";
  EXPECT_GT(visible, scene.size() / 4) << "the test scene should be mostly visible";
  EXPECT_LT(visible, scene.size()) << "the test scene should have culled Gaussians";
  EXPECT_EQ(gpu.draw.count, 4u);
  EXPECT_NEAR(double(gpu.draw.instance_count), double(visible), double(integer_mismatches));
}

TEST(GlSplatPreprocess, MatchesTheCpuPreprocessOnARandomCloudWithNearCulls) {
  HeadlessContext context;
  // Depths from 0.05: the Gaussians before z = 0.2 are culled.
  const auto scene = render::testing::random_cloud(3000, 0.05f, 12.0f, 17);
  const auto camera = render::make_look_at_camera({0.3f, 0.1f, -0.5f}, {0, 0, 6}, {0, 1, 0}, 0.7f, 128, 96);
  expect_matches_cpu(context, scene, camera, {});
}

TEST(GlSplatPreprocess, MatchesTheCpuPreprocessAtShDegree3OffAxisWithEverySetting) {
  HeadlessContext context;
  render::SceneGeneratorOptions options;
  options.count = 3000;
  options.sh_degree = 3;
  options.seed = 5;
  const auto scene = render::generate_scene(options);
  const auto base = render::make_look_at_camera({0, -1, -5}, {0, 0, 0}, {0, -1, 0}, 0.8f, 128, 112);
  const auto geometry = render::make_quilt_geometry(base, 5.1f, 40.0f, 9);
  const render::Camera off_axis = geometry.view_camera(0);
  ASSERT_NE(off_axis.shift_x_ndc, 0.0f);
  expect_matches_cpu(context, scene, off_axis, {});
  render::RasterSettings settings;
  settings.dilation_px2 = 0.7f;
  settings.scale_modifier = 1.3f;
  settings.sh_degree = 2;
  settings.sh_origin = glm::vec3(0.5f, -1.0f, -6.0f);
  expect_matches_cpu(context, scene, geometry.view_camera(7), settings);
}

TEST(GlSplatPreprocess, AnEmptySceneDrawsNothing) {
  HeadlessContext context;
  scene::GaussianScene empty;
  const auto camera = render::make_look_at_camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0.7f, 32, 32);
  const GpuPreprocess gpu = run_gpu(context, empty, camera, {});
  EXPECT_EQ(gpu.draw.count, 4u);
  EXPECT_EQ(gpu.draw.instance_count, 0u);
}

}  // namespace
}  // namespace lfd::gpu
