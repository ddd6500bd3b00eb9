// The compute tile rasterizer (--raster compute; gpu/gl_tile_splats.hpp, gpu/gl_tile_keys.hpp)
// against the CPU reference rasterizer on llvmpipe, with the GL per-view tests' bars
// (gl_per_view_test.cpp: >= 40 dB colour and transmittance): views, quilts in float and RGBA8,
// a scene of huge splats (the per-work-group keys), a dense tile (many batches, the early stop),
// and the hardware path's quilt of the same scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "../test_data.hpp"
#include "gl_view_compare.hpp"
#include "gpu/gl_context.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_tile_keys.hpp"
#include "gpu/gl_tile_splats.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/preprocess.hpp"
#include "render/rasterizer_cpu.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"

namespace lfd::gpu {
namespace {

using testing::kMinPsnrDb;
using testing::tabletop_camera;

GlPerViewOptions compute_options() {
  GlPerViewOptions o;
  o.raster = RasterPath::kCompute;
  return o;
}

scene::GaussianScene generated_scene(int sh_degree, size_t count) { return testing::generated_scene(sh_degree, count); }

double compare_view(GlPerViewRenderer& renderer, const scene::GaussianScene& scene, const render::Camera& camera,
                    const render::RasterSettings& settings, const std::string& what) {
  return testing::compare_view(renderer, scene, camera, settings, "compute " + what);
}

TEST(GlTileKeys, SlotBitsHoldEverySlot) {
  EXPECT_EQ(slot_bits(1), 1);
  EXPECT_EQ(slot_bits(2), 1);
  EXPECT_EQ(slot_bits(3), 2);
  EXPECT_EQ(slot_bits(1024), 10);
  EXPECT_EQ(slot_bits(1025), 11);
  EXPECT_EQ(slot_bits(45u * 1824u), 17);
}

TEST(GlTileSplats, ViewsOfAGeneratedSceneMatchTheCpuAtShDegrees0And3) {
  HeadlessContext context;
  const auto scene = generated_scene(3, 4000);
  GlScene gl_scene(scene, context.info());
  GlPerViewRenderer renderer(gl_scene, compute_options());
  testing::compare_generated_views(renderer, scene, "compute ");
}

TEST(GlTileSplats, TheFixtureAndDemoScenesMatchTheCpu) {
  HeadlessContext context;
  for (const auto& path : {test::fixture_scene("three-points.ply"), test::project_data() / "scenes" / "demo.ply"}) {
    const auto scene = scene::load_gaussian_scene(path);
    const auto camera = render::camera_from_spec(render::frame_scene(scene), 128, 128);
    GlScene gl_scene(scene, context.info());
    GlPerViewRenderer renderer(gl_scene, compute_options());
    compare_view(renderer, scene, camera, {}, path.filename().string());
  }
}

// Mostly opaque: pixels stop early and whole tiles stop taking batches.
TEST(GlTileSplats, ADenseViewWhereTheReferenceStopsEarlyMatchesTheCpu) {
  HeadlessContext context;
  const auto scene = generated_scene(1, 60000);
  GlScene gl_scene(scene, context.info());
  GlPerViewRenderer renderer(gl_scene, compute_options());
  compare_view(renderer, scene, tabletop_camera(), {}, "generated 60k, mostly opaque");
}

// Splats far larger than the image: their rectangles hold every tile, so their keys are
// counted and written by a work group each (tile_splat_huge.comp.glsl); faint ones too, whose
// opacity-aware ellipse covers fewer tiles than their rectangle.
TEST(GlTileSplats, HugeSplatsMatchTheCpu) {
  HeadlessContext context;
  auto scene = generated_scene(0, 2000);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int k = 0; k < 200; ++k) {
    scene.positions.push_back({u(rng) * 2 - 1, u(rng) * 2 - 1, u(rng) * 2 - 1});
    scene.scales.push_back({0.5f + u(rng), 0.5f + u(rng), 0.05f + 0.2f * u(rng)});
    scene.rotations.push_back({1.0f, 0.0f, 0.0f, 0.0f});
    scene.opacities.push_back(k % 2 ? 0.02f + 0.05f * u(rng) : 0.3f * u(rng));
    for (int c = 0; c < 3; ++c) scene.sh.push_back(u(rng) - 0.5f);
  }
  GlScene gl_scene(scene, context.info());
  GlPerViewRenderer renderer(gl_scene, compute_options());
  compare_view(renderer, scene, tabletop_camera(), {}, "200 huge splats in 2k");
  compare_view(renderer, scene, tabletop_camera(200, 150), {}, "200 huge splats in 2k, 200x150");

  // The huge splats did take the per-work-group path, and the opacity-aware cover left out tiles
  // of their rectangles: fewer keys than the rectangles' tiles.
  GlTileSplats tiles;
  const render::Camera camera = tabletop_camera();
  Texture view(GL_RGBA32F, camera.width, camera.height);
  tiles.render_views(gl_scene, std::span(&camera, 1), {},
                     {.texture = &view, .cols = 1, .cell_size = {camera.width, camera.height}});
  const uint32_t huge = tiles.read_huge_items();
  std::printf("[ keys ] %u keys, %u items keyed by a work group each\n", tiles.counts().keys, huge);
  EXPECT_GT(huge, 50u);
  size_t rectangle_tiles = 0;
  for (const render::ProjectedGaussian& g : render::preprocess(scene, camera, {}))
    if (g.radius_px > 0) rectangle_tiles += size_t(g.rect_max.x - g.rect_min.x) * size_t(g.rect_max.y - g.rect_min.y);
  EXPECT_LT(tiles.counts().keys, rectangle_tiles);
  EXPECT_EQ(tiles.passes(), 1);
}

// Thousands of small splats in one 16x16 tile: its list spans many 256-splat batches.
TEST(GlTileSplats, ADenseTileMatchesTheCpu) {
  HeadlessContext context;
  scene::GaussianScene scene;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int k = 0; k < 5000; ++k) {
    scene.positions.push_back({0.05f * (u(rng) - 0.5f), 0.05f * (u(rng) - 0.5f), 2.0f * (u(rng) - 0.5f)});
    scene.scales.push_back({0.002f + 0.01f * u(rng), 0.002f + 0.01f * u(rng), 0.002f + 0.01f * u(rng)});
    scene.rotations.push_back({1.0f, 0.0f, 0.0f, 0.0f});
    scene.opacities.push_back(0.02f + 0.1f * u(rng));
    for (int c = 0; c < 3; ++c) scene.sh.push_back(u(rng) - 0.5f);
  }
  const auto camera = tabletop_camera();
  GlScene gl_scene(scene, context.info());
  GlPerViewOptions options = compute_options();
  GlPerViewRenderer renderer(gl_scene, options);
  compare_view(renderer, scene, camera, {}, "5000 splats in one tile");
}

// The whole quilt in one pass (testing::QuiltCase: 9 views in a 4x3 grid), in float and RGBA8;
// in passes of 2 views; and the same quilt from the hardware path.
void compare_quilt(GLenum format, const std::string& what) {
  HeadlessContext context;
  const testing::QuiltCase c;
  GlScene gl_scene(c.scene, context.info());
  GlPerViewOptions options = compute_options();
  options.gpu_timers = true;
  GlPerViewRenderer renderer(gl_scene, options);
  const ImageF gl = testing::compare_quilt_with_cpu(renderer, c, format, "compute quilt " + what);
  EXPECT_GT(renderer.stats().memory_bytes, gl_scene.bytes());

  // Views in passes of 2 (as on a GPU whose storage buffers hold 2 views of records): the same
  // quilt, bit for bit.
  GlPerViewOptions split = compute_options();
  split.compute_entries_per_pass = 2 * c.scene.size() + 1;
  GlPerViewRenderer in_passes(gl_scene, split);
  Texture passes_quilt(format, c.layout.width, c.layout.height);
  in_passes.render_quilt(c.geometry, c.layout, {}, passes_quilt);
  EXPECT_EQ(read_image_top_down(passes_quilt).pixels, gl.pixels) << what;

  GlPerViewRenderer hardware(gl_scene);
  Texture hardware_quilt(format, c.layout.width, c.layout.height);
  hardware.render_quilt(c.geometry, c.layout, {}, hardware_quilt);
  const double paths = render::psnr(gl, read_image_top_down(hardware_quilt));
  std::printf("[ psnr ] compute vs hardware quilt %s: %.1f dB\n", what.c_str(), paths);
  EXPECT_GE(paths, kMinPsnrDb) << what;
}

TEST(GlTileSplats, FloatQuiltMatchesTheCpuPerViewQuilt) { compare_quilt(GL_RGBA32F, "RGBA32F"); }
TEST(GlTileSplats, Rgba8QuiltMatchesTheCpuPerViewQuilt) { compare_quilt(GL_RGBA8, "RGBA8"); }

TEST(GlTileSplats, AutoMustBeResolvedFirst) {
  HeadlessContext context;
  const auto scene = generated_scene(0, 10);
  GlScene gl_scene(scene, context.info());
  GlPerViewOptions options;
  options.raster = RasterPath::kAuto;
  EXPECT_THROW(GlPerViewRenderer(gl_scene, options), std::invalid_argument);
}

}  // namespace
}  // namespace lfd::gpu
