// The compute tile rasterizer (--raster compute; gpu/splats/gl_splat_tile_raster.hpp, gpu/compute/gl_tile_keys.hpp)
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
#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/compute/gl_tile_keys.hpp"
#include "gpu/splats/gl_splat_tile_raster.hpp"
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

TEST(GlSplatTileRaster, ViewsOfAGeneratedSceneMatchTheCpuAtShDegrees0And3) {
  HeadlessContext context;
  const auto scene = generated_scene(3, 4000);
  GlScene gl_scene(scene, context.info());
  GlPerViewRenderer renderer(gl_scene, compute_options());
  testing::compare_generated_views(renderer, scene, "compute ");
}

TEST(GlSplatTileRaster, TheFixtureAndDemoScenesMatchTheCpu) {
  HeadlessContext context;
  for (const auto& path : {test::fixture_scene("three-points.ply"), test::project_data() / "scenes" / "demo.ply"}) {
    const auto scene = scene::load_gaussian_scene(path);
    const auto camera = render::camera_from_spec(render::frame_scene(scene), 128, 128);
    GlScene gl_scene(scene, context.info());
    GlPerViewRenderer renderer(gl_scene, compute_options());
    compare_view(renderer, scene, camera, {}, path.filename().string());
  }
}

// The slots split into parts by a GlSplatTileRaster of `split_keys` on one view (0, 0: none split).
std::pair<uint32_t, uint32_t> split_counts(const GlScene& gl_scene, const render::Camera& camera, uint32_t split_keys) {
  GlSplatTileRaster tiles;
  tiles.set_split_keys(split_keys);
  Texture view(GL_RGBA32F, camera.width, camera.height);
  tiles.render_views(gl_scene, std::span(&camera, 1), {},
                     {.texture = &view, .cols = 1, .cell_size = {camera.width, camera.height}});
  return tiles.read_split_counts();
}

// Mostly opaque: pixels stop early and whole tiles stop taking batches. Split into parts of 64
// keys (hot tiles forced: most slots are split, and most pixels stop inside a part, where the
// merge replays it from the true T), the view still equals the CPU's and the unsplit one.
TEST(GlSplatTileRaster, ADenseViewWhereTheReferenceStopsEarlyMatchesTheCpu) {
  HeadlessContext context;
  const auto scene = generated_scene(1, 60000);
  GlScene gl_scene(scene, context.info());
  const auto camera = tabletop_camera();
  GlPerViewRenderer renderer(gl_scene, compute_options());
  compare_view(renderer, scene, camera, {}, "generated 60k, mostly opaque");
  GlPerViewOptions split = compute_options();
  split.compute_split_keys = 64;
  GlPerViewRenderer split_renderer(gl_scene, split);
  compare_view(split_renderer, scene, camera, {}, "generated 60k, mostly opaque, tiles split every 64 keys");
  const render::RasterImage whole = renderer.render_view_image(camera);
  const render::RasterImage parts = split_renderer.render_view_image(camera);
  const double db = render::psnr(testing::rgb_of(parts), testing::rgb_of(whole));
  std::printf("[ psnr ] split every 64 keys vs whole slots: %.1f dB\n", db);
  EXPECT_GE(db, 100.0);  // the same image up to the rounding of the merged products
  const auto [slots, parts_count] = split_counts(gl_scene, camera, 64);
  std::printf("[ split ] %u slots in %u parts\n", slots, parts_count);
  EXPECT_GT(slots, 20u);
  EXPECT_GT(parts_count, 2 * slots - 1);
}

// Splats far larger than the image: their rectangles hold every tile, so their keys are
// counted and written by a work group each (splat_tile_huge.comp.glsl); faint ones too, whose
// opacity-aware ellipse covers fewer tiles than their rectangle.
TEST(GlSplatTileRaster, HugeSplatsMatchTheCpu) {
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
  GlSplatTileRaster tiles;
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
TEST(GlSplatTileRaster, ADenseTileMatchesTheCpu) {
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
  // Split off, at the default threshold (the hot tile holds more), and forced small (every tile
  // over 100 keys in parts).
  for (const uint32_t split_keys : {0u, kTileSplatSplitKeys, 100u}) {
    GlPerViewOptions options = compute_options();
    options.compute_split_keys = split_keys;
    GlPerViewRenderer renderer(gl_scene, options);
    compare_view(renderer, scene, camera, {}, "5000 splats in one tile, split keys " + std::to_string(split_keys));
  }
  EXPECT_EQ(split_counts(gl_scene, camera, 0).first, 0u);
  const auto [slots, parts] = split_counts(gl_scene, camera, kTileSplatSplitKeys);
  EXPECT_GE(slots, 1u) << "the hot tile was split at the default threshold";
  EXPECT_GE(parts, 2u);
  EXPECT_GT(split_counts(gl_scene, camera, 100).second, parts) << "smaller parts, more of them";
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
  split.compute_pass_limit = (2 * c.scene.size() + 1) * sizeof(SplatRecord);
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

// Nothing is read back inside a frame (docs/gpu.md "Memory and passes"): keys go into buffers of
// a capacity kept from frame to frame, and a pass whose keys outgrew it is drawn again. From a
// capacity of 64 keys every pass of a 9-view quilt (passes of 2 views) overflows and is redrawn,
// and the quilt is the one drawn with room to spare, bit for bit; the next frame redraws nothing.
TEST(GlSplatTileRaster, PassesWhoseKeysOutgrowTheCapacityAreDrawnAgain) {
  HeadlessContext context;
  const testing::QuiltCase c;
  GlScene gl_scene(c.scene, context.info());
  std::vector<render::Camera> cameras;
  for (int v = 0; v < c.geometry.views; ++v) cameras.push_back(c.geometry.view_camera(v));
  const auto draw = [&](GlSplatTileRaster& tiles) {
    Texture quilt(GL_RGBA32F, c.layout.width, c.layout.height);
    const glm::ivec2 cell{c.layout.tile_width(), c.layout.tile_height()};
    tiles.render_views(gl_scene, cameras, {}, {.texture = &quilt, .cols = c.layout.cols, .cell_size = cell});
    return read_image_top_down(quilt).pixels;
  };
  GlSplatTileRaster roomy;
  roomy.set_key_capacity(1'000'000);
  const std::vector<float> truth = draw(roomy);
  EXPECT_EQ(roomy.redrawn_passes(), 0);
  GlSplatTileRaster tight;
  tight.set_pass_limit((2 * c.scene.size() + 1) * sizeof(SplatRecord));
  tight.set_key_capacity(64);
  EXPECT_EQ(draw(tight), truth);
  EXPECT_EQ(tight.passes(), 5);
  EXPECT_EQ(tight.redrawn_passes(), 5);
  EXPECT_EQ(tight.counts().keys, roomy.counts().keys);
  EXPECT_GT(tight.key_capacity(), tight.counts().keys / 5);
  std::printf("[ keys ] %u keys; capacity grown from 64 to %u\n", tight.counts().keys, tight.key_capacity());
  EXPECT_EQ(draw(tight), truth);
  EXPECT_EQ(tight.redrawn_passes(), 0);
}

TEST(GlSplatTileRaster, FloatQuiltMatchesTheCpuPerViewQuilt) { compare_quilt(GL_RGBA32F, "RGBA32F"); }
TEST(GlSplatTileRaster, Rgba8QuiltMatchesTheCpuPerViewQuilt) { compare_quilt(GL_RGBA8, "RGBA8"); }

TEST(GlSplatTileRaster, AutoMustBeResolvedFirst) {
  HeadlessContext context;
  const auto scene = generated_scene(0, 10);
  GlScene gl_scene(scene, context.info());
  GlPerViewOptions options;
  options.raster = RasterPath::kAuto;
  EXPECT_THROW(GlPerViewRenderer(gl_scene, options), std::invalid_argument);
}

}  // namespace
}  // namespace lfd::gpu
