// The GL per-view renderer against the CPU reference rasterizer (gpu/splats/gl_per_view_renderer.hpp),
// on llvmpipe: views and quilts by PSNR (docs/gpu.md "Per-view renderer": >= 40 dB), the layered raster of G2LF's
// planes against the CPU's subsets, and scenes too large for the GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "../test_data.hpp"
#include "gl_view_compare.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/rasterizer_cpu.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"

namespace lfd::gpu {
namespace {

using testing::compare_view;
using testing::generated_scene;
using testing::kMinPsnrDb;
using testing::rgb_of;
using testing::tabletop_camera;
using testing::to_image;

TEST(GlPerView, ViewsOfAGeneratedSceneMatchTheCpuAtShDegrees0And3) {
  HeadlessContext context;
  const auto scene = generated_scene(3);
  GlScene gl_scene(scene, context.info());
  GlPerViewRenderer renderer(gl_scene);
  testing::compare_generated_views(renderer, scene, "");
}

TEST(GlPerView, TheFixtureAndDemoScenesMatchTheCpu) {
  HeadlessContext context;
  const auto demo = test::project_data() / "scenes" / "demo.ply";
  for (const auto& path : {test::fixture_scene("three-points.ply"), demo}) {
    const auto scene = scene::load_gaussian_scene(path);
    const render::CameraSpec framing = render::frame_scene(scene);
    const auto camera = render::camera_from_spec(framing, 128, 128);
    GlScene gl_scene(scene, context.info());
    GlPerViewRenderer renderer(gl_scene);
    compare_view(renderer, scene, camera, {}, path.filename().string());
    const float focal_distance = glm::length(framing.look_at - framing.position);
    const auto geometry = render::make_quilt_geometry(camera, focal_distance, 40.0f, 9);
    compare_view(renderer, scene, geometry.view_camera(1), {}, path.filename().string() + " off-axis view 1/9");
  }
}

// Where most pixels become opaque the reference stops blending before T < 1e-4 and GL blends
// on (gpu/splats/gl_splat_raster.hpp); the difference stays far below the bar.
TEST(GlPerView, ADenseViewWhereTheReferenceStopsEarlyMatchesTheCpu) {
  HeadlessContext context;
  const auto scene = generated_scene(1, 60000);
  const auto camera = tabletop_camera();
  const render::RasterImage cpu = render::rasterize(scene, camera, {});
  const auto opaque = std::count_if(cpu.transmittance.begin(), cpu.transmittance.end(), [](float t) { return t < 0.01f; });
  ASSERT_GT(double(opaque), 0.5 * double(cpu.transmittance.size())) << "the scene should be dense";
  GlScene gl_scene(scene, context.info());
  GlPerViewRenderer renderer(gl_scene);
  compare_view(renderer, scene, camera, {}, "generated 60k, mostly opaque");
}

TEST(GlPerView, Rgba16fAccumulationStaysAbove40Db) {
  HeadlessContext context;
  const auto scene = generated_scene(1);
  GlScene gl_scene(scene, context.info());
  GlPerViewOptions options;
  options.accumulation_format = GL_RGBA16F;
  GlPerViewRenderer renderer(gl_scene, options);
  compare_view(renderer, scene, tabletop_camera(), {}, "generated, RGBA16F target");
}

// The viewer's 24-bit depth keys (3 radix passes): only depths within 2^-15 of each other change
// order, so the views stay close to the CPU's (measured 62-78 dB against 80-84 dB exact), and
// the option does change the image (else the sort would not have used it).
TEST(GlPerView, TwentyFourBitDepthKeysStayCloseToTheCpu) {
  HeadlessContext context;
  const auto scene = scene::load_gaussian_scene(test::project_data() / "scenes" / "demo.ply");
  const auto camera = render::camera_from_spec(render::frame_scene(scene), 128, 128);
  GlScene gl_scene(scene, context.info());
  GlPerViewOptions options;
  options.depth_key_bits = 24;
  GlPerViewRenderer coarse(gl_scene, options);
  const double psnr_24 = compare_view(coarse, scene, camera, {}, "demo.ply, 24-bit depth keys");
  GlPerViewRenderer exact(gl_scene);
  const double psnr_32 = compare_view(exact, scene, camera, {}, "demo.ply, 32-bit depth keys");
  EXPECT_GE(psnr_24, 55.0);
  EXPECT_LT(psnr_24, psnr_32);
  options.depth_key_bits = 12;
  EXPECT_THROW(GlPerViewRenderer(gl_scene, options), std::invalid_argument);
}

// 16-bit keys normalised to the visible depth range (2 radix passes) order about as finely as
// 24 float bits (3 passes): demo.ply stays as close to the CPU as the viewer's 24-bit keys
// (within 3 dB; 16 float bits, which spend 9 on sign and exponent, measured 38 dB). Sorting
// the visible splats only (the default) is exact: the image equals the sort over all N.
TEST(GlPerView, NormalisedSixteenBitKeysAndTheVisibleOnlySortStayCloseToTheCpu) {
  HeadlessContext context;
  const auto scene = scene::load_gaussian_scene(test::project_data() / "scenes" / "demo.ply");
  const auto camera = render::camera_from_spec(render::frame_scene(scene), 128, 128);
  GlScene gl_scene(scene, context.info());
  GlPerViewOptions options;
  options.depth_key_bits = 24;
  GlPerViewRenderer float24(gl_scene, options);
  const double psnr_24 = compare_view(float24, scene, camera, {}, "demo.ply, 24-bit float keys");
  options.depth_key_bits = 16;
  options.normalised_depth_keys = true;
  GlPerViewRenderer normalised16(gl_scene, options);
  const double psnr_n16 = compare_view(normalised16, scene, camera, {}, "demo.ply, 16-bit normalised keys");
  EXPECT_GE(psnr_n16, psnr_24 - 3.0);
  GlPerViewRenderer exact(gl_scene);
  EXPECT_LT(psnr_n16, compare_view(exact, scene, camera, {}, "demo.ply, 32-bit float keys"));  // the keys are coarser
  options.depth_key_bits = 32;
  EXPECT_THROW(GlPerViewRenderer(gl_scene, options), std::invalid_argument);

  GlPerViewOptions all_n;
  all_n.sort_visible_only = false;
  GlPerViewRenderer full(gl_scene, all_n);
  GlPerViewRenderer visible(gl_scene);
  const render::Camera off_axis = render::make_quilt_geometry(camera, 5.0f, 40.0f, 9).view_camera(0);
  const render::RasterImage a = full.render_view_image(off_axis), b = visible.render_view_image(off_axis);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(a.transmittance, b.transmittance);
}

void compare_quilt(GLenum format, const std::string& what) {
  HeadlessContext context;
  const testing::QuiltCase c;
  GlScene gl_scene(c.scene, context.info());
  GlPerViewOptions options;
  options.gpu_timers = true;
  GlPerViewRenderer renderer(gl_scene, options);
  testing::compare_quilt_with_cpu(renderer, c, format, "quilt " + what);
  const GlPerViewStats& stats = renderer.stats();
  std::printf("[ stats ] quilt %s: preprocess %.4f s, sort %.4f s, raster %.4f s, %.1f MiB\n", what.c_str(),
              stats.preprocess_s, stats.sort_s, stats.raster_s, stats.memory_bytes / 1048576.0);
  EXPECT_GE(stats.memory_bytes, gl_scene.bytes());
}

TEST(GlPerView, FloatQuiltMatchesTheCpuPerViewQuilt) { compare_quilt(GL_RGBA32F, "RGBA32F"); }
TEST(GlPerView, Rgba8QuiltMatchesTheCpuPerViewQuilt) { compare_quilt(GL_RGBA8, "RGBA8"); }

// G2LF's use: one draw routes each sorted splat to a layer; with a zero background each layer
// holds (C, T) of its splats, as render::rasterize of that subset.
TEST(GlPerView, LayeredRasterDrawsEachSplatIntoItsLayer) {
  HeadlessContext context;
  const auto scene = generated_scene(1, 3000);
  const auto camera = tabletop_camera(96, 96);
  GlScene gl_scene(scene, context.info());
  GlSplatPreprocess preprocess;
  GlRadixSort sort;
  GlSplatRaster raster;
  SplatBuffers buffers;
  preprocess.run(gl_scene, camera, {}, buffers);
  sort.sort(buffers.keys, buffers.values, uint32_t(scene.size()));
  DrawArraysIndirect draw{};
  buffers.draw.download(&draw, sizeof(draw));
  const auto sorted = buffers.values.download_as<uint32_t>(draw.instance_count);
  // Alternate layers in blocks of 100 along the depth order: both layers overlap in depth.
  std::vector<uint32_t> layers(sorted.size());
  std::vector<uint32_t> subsets[2];
  for (size_t i = 0; i < sorted.size(); ++i) {
    layers[i] = uint32_t((i / 100) % 2);
    subsets[layers[i]].push_back(sorted[i]);
  }
  Buffer layer_buffer(layers.size() * 4, layers.data());
  Texture planes(GL_RGBA32F, camera.width, camera.height, 2);
  Framebuffer framebuffer;
  framebuffer.attach(0, planes);
  framebuffer.finish(1);
  SplatRasterTarget target;
  target.framebuffer = framebuffer.id();
  target.image_size = {camera.width, camera.height};
  raster.clear(target);
  raster.draw(buffers, target, &layer_buffer);
  for (int layer = 0; layer < 2; ++layer) {
    std::sort(subsets[layer].begin(), subsets[layer].end());
    const render::RasterImage cpu = render::rasterize(scene, camera, {}, subsets[layer]);
    const std::vector<float> texels = read_texture_rgba(planes, layer);
    ImageF gl_c(camera.width, camera.height, 3), gl_t(camera.width, camera.height, 1);
    for (int y = 0; y < camera.height; ++y)
      for (int x = 0; x < camera.width; ++x) {
        const float* t = texels.data() + (size_t(camera.height - 1 - y) * camera.width + x) * 4;
        for (int c = 0; c < 3; ++c) gl_c.at(x, y, c) = t[c];
        gl_t.at(x, y, 0) = t[3];
      }
    const double c_db = render::psnr(gl_c, rgb_of(cpu));
    const double t_db = render::psnr(gl_t, to_image(cpu.transmittance, cpu.width, cpu.height, 1));
    std::printf("[ psnr ] layer %d: C %.1f dB, T %.1f dB\n", layer, c_db, t_db);
    EXPECT_GE(c_db, kMinPsnrDb) << layer;
    EXPECT_GE(t_db, kMinPsnrDb) << layer;
  }
}

TEST(GlPerView, ASceneTooLargeIsOneInputErrorLineNamingTheNumbersAndTheRemedy) {
  HeadlessContext context;
  GlInfo small = context.info();
  small.max_ssbo_bytes = 128ll << 20;
  try {
    check_scene_fits(3'000'000, 3, small);
    FAIL() << "3M Gaussians at SH degree 3 fit 128 MiB buffers";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("3000000"), std::string::npos) << message;
    EXPECT_NE(message.find("--sh-degree"), std::string::npos) << message;
    EXPECT_NE(message.find("128 MiB"), std::string::npos) << message;
  }
  GlInfo little_memory = context.info();
  little_memory.free_memory_bytes = 64ll << 20;
  EXPECT_THROW(check_scene_fits(1'000'000, 0, little_memory), InputError);
  EXPECT_NO_THROW(check_scene_fits(100'000, 0, little_memory));
  // The constructor checks before it allocates anything.
  GlInfo tiny = context.info();
  tiny.max_ssbo_bytes = 1024;
  const size_t before = gpu_bytes_allocated();
  EXPECT_THROW(GlScene(generated_scene(3, 100), tiny), InputError);
  EXPECT_EQ(gpu_bytes_allocated(), before);
  // Lowering the degree is the remedy the message names.
  GlSceneOptions degree0;
  degree0.max_sh_degree = 0;
  tiny.max_ssbo_bytes = 100 * 64;
  EXPECT_NO_THROW(GlScene(generated_scene(3, 100), tiny, degree0));
}

TEST(GlPerView, UploadReportsProgressAndTheUploadedDegree) {
  HeadlessContext context;
  const auto scene = generated_scene(3, 500);
  size_t last = 0;
  GlSceneOptions options;
  options.max_sh_degree = 1;
  options.progress = [&](size_t done, size_t total) {
    EXPECT_EQ(total, scene.size());
    EXPECT_GT(done, last);
    last = done;
  };
  GlScene gl_scene(scene, context.info(), options);
  EXPECT_EQ(last, scene.size());
  EXPECT_EQ(gl_scene.sh_degree(), 1);
  EXPECT_EQ(gl_scene.sh().bytes(), scene.size() * 3 * 16);
}

TEST(GlPerView, TheLargestShDegreeThatFitsIsChosen) {
  // 1000 Gaussians need 48 + 192/112/48/16 bytes of scene and 80 of render buffers each at SH
  // degree 3/2/1/0: 320, 240, 176 and 144 kB.
  GlInfo info;
  EXPECT_EQ(fitting_sh_degree(1000, 3, info), 3);  // no limits known
  info.free_memory_bytes = 320'000;
  EXPECT_EQ(fitting_sh_degree(1000, 3, info), 3);
  info.free_memory_bytes = 319'999;
  EXPECT_EQ(fitting_sh_degree(1000, 3, info), 2);
  info.free_memory_bytes = 200'000;
  EXPECT_EQ(fitting_sh_degree(1000, 3, info), 1);
  EXPECT_EQ(fitting_sh_degree(1000, 0, info), 0);  // never above the scene's own degree
  info.free_memory_bytes = 150'000;
  EXPECT_EQ(fitting_sh_degree(1000, 3, info), 0);
  info.free_memory_bytes = 100'000;
  try {
    fitting_sh_degree(1000, 3, info);
    FAIL() << "1000 Gaussians fit 100 kB at degree 0";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("SH degree 0"), std::string::npos) << e.what();
  }
  // A per-buffer limit: the SH buffer of degree 3 (12 vec4s, 192 B) and 2 (112 B) exceed
  // 100 kB for 1000 Gaussians, degree 1 (48 kB) and the records (64 kB) do not.
  GlInfo buffers;
  buffers.max_ssbo_bytes = 100'000;
  EXPECT_EQ(fitting_sh_degree(1000, 3, buffers), 1);
  buffers.max_ssbo_bytes = 60'000;  // the 64 kB record buffer fits at no degree
  EXPECT_THROW(fitting_sh_degree(1000, 3, buffers), InputError);
}

TEST(GlPerView, UploadInSmallPiecesGivesTheSameBuffers) {
  HeadlessContext context;
  const auto scene = generated_scene(3, 1000);
  const GlScene whole(scene, context.info());
  GlSceneOptions pieces;
  pieces.chunk_gaussians = 128;
  int calls = 0;
  pieces.progress = [&](size_t, size_t) { ++calls; };
  const GlScene chunked(scene, context.info(), pieces);
  EXPECT_EQ(calls, 8);  // ceil(1000 / 128)
  auto same = [](const Buffer& a, const Buffer& b) {
    return a.download_as<float>(a.bytes() / 4) == b.download_as<float>(b.bytes() / 4);
  };
  EXPECT_TRUE(same(whole.positions(), chunked.positions()));
  EXPECT_TRUE(same(whole.scales(), chunked.scales()));
  EXPECT_TRUE(same(whole.rotations(), chunked.rotations()));
  EXPECT_TRUE(same(whole.sh(), chunked.sh()));
}

}  // namespace
}  // namespace lfd::gpu
