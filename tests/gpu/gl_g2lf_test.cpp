// G2LF on the GPU against the CPU reference, stage by stage (render/g2lf.hpp): the swizzle pass
// on the CPU's own planes, the depth binning, and the whole renderer, on real EGL contexts
// (llvmpipe here). Images are small: llvmpipe runs compute shaders on the CPU.
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_depth_binning.hpp"
#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/compute/gl_radix_sort.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/planes/gl_swizzle.hpp"
#include "render/depth_binning.hpp"
#include "render/g2lf.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "../test_data.hpp"
#include "../render/render_test_scenes.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

using render::ChunkBinning;
using render::PlaneFilter;
using render::PlanePrecision;

HeadlessContext& context() {
  static HeadlessContext c;
  return c;
}

// A scene seen through one quilt geometry, with its reference camera for some G2LF options.
struct TestScene {
  std::string name;
  scene::GaussianScene scene;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
  glm::vec3 background{0.0f};
};

// Random Gaussians in front of a camera at the origin; 9 views of 64x48 in a 3x3 quilt.
const TestScene& cloud() {
  static const TestScene s = [] {
    TestScene s;
    s.name = "cloud";
    s.scene = render::testing::random_cloud(3000, 2.5f, 6.0f, 11);
    const auto base = render::make_look_at_camera({0, 0, 0}, {0, 0, 3.5f}, {0, 1, 0}, 0.6f, 64, 48);
    s.geometry = render::make_quilt_geometry(base, 3.5f, 40.0f, 9);
    s.layout = render::make_quilt_layout(s.geometry, 3, 3);
    return s;
  }();
  return s;
}

// The generated tabletop (ground, objects at several depths, background), 10 views of 56x40 in
// a 4x3 quilt with a margin (the tiles do not fill the texture) and a grey background.
const TestScene& tabletop() {
  static const TestScene s = [] {
    TestScene s;
    s.name = "tabletop";
    render::SceneGeneratorOptions g;
    g.count = 4000;
    g.seed = 3;
    s.scene = render::generate_scene(g);
    const auto base = render::make_look_at_camera({0, -1, -5}, {0, 0, 0}, {0, -1, 0}, 0.7f, 56, 40);
    s.geometry = render::make_quilt_geometry(base, 5.1f, 50.0f, 10);
    s.layout = render::make_quilt_layout(s.geometry, 4, 3);
    s.layout.width += 5;
    s.layout.height += 3;
    s.background = {0.2f, 0.3f, 0.4f};
    return s;
  }();
  return s;
}

// Fraction of a tile-covered quilt's pixels that differ from the background: a comparison
// of two empty quilts would prove nothing.
double scene_pixel_fraction(const ImageF& quilt, const TestScene& s) {
  size_t differ = 0, total = 0;
  for (int j = 0; j < s.geometry.views; ++j)
    for (int y = 0; y < s.geometry.base.height; ++y)
      for (int x = 0; x < s.geometry.base.width; ++x) {
        const int qx = s.layout.tile_x(j) + x, qy = s.layout.tile_y_top_down(j) + y;
        float d = 0.0f;
        for (int c = 0; c < 3; ++c) d += std::fabs(quilt.at(qx, qy, c) - s.background[c]);
        differ += d > 0.02f;
        ++total;
      }
  return double(differ) / double(total);
}

// ---- Stage 3: the swizzle pass on the CPU's planes ----

struct SwizzleCase {
  const TestScene& (*setup)();
  int plane_scale;
  float d_shift;
  PlanePrecision precision;
  PlaneFilter filter;
};

double swizzle_psnr(const SwizzleCase& c, double* max_error, const SwizzleOptions& swizzle_options = {}) {
  context();
  const TestScene& s = c.setup();
  render::G2lfOptions o;
  o.chunks = 24;
  o.plane_scale = c.plane_scale;
  o.d_shift = c.d_shift;
  const render::ReferenceCamera ref = render::reference_camera(o, s.geometry);
  const render::DepthChunks chunks = render::bin_by_depth(s.scene, s.geometry, ref, o.chunks, o.binning);
  render::RasterSettings settings;
  settings.dilation_px2 = render::adaptive_filter_variance(s.geometry, ref, o.plane_scale);
  const render::SweepingPlanes planes =
      render::render_sweeping_planes(s.scene, s.geometry, ref, chunks, c.precision, settings);
  ImageF cpu(s.layout.width, s.layout.height, 3, 0.0f);
  render::swizzle_blend(planes, s.geometry, ref, s.layout, c.filter, s.background, cpu);

  const GlPlanes gl_planes = upload_planes(planes);
  const Texture quilt = make_quilt_texture(s.layout, GL_RGBA32F);
  GlSwizzle swizzle(swizzle_options);
  swizzle.run(gl_planes, s.geometry, ref, s.layout, c.filter, s.background, quilt);
  const ImageF gl = read_image_top_down(quilt);
  EXPECT_GT(scene_pixel_fraction(cpu, s), 0.2) << "the planes must show the scene";
  *max_error = 0.0;
  for (size_t i = 0; i < gl.pixels.size(); ++i)
    *max_error = std::max(*max_error, double(std::fabs(gl.pixels[i] - cpu.pixels[i])));
  return render::psnr(gl, cpu);
}

class GlG2lfSwizzle : public ::testing::TestWithParam<SwizzleCase> {};

TEST_P(GlG2lfSwizzle, MatchesTheCpuSwizzleOnTheSamePlanes) {
  double max_error = 0.0;
  const double p = swizzle_psnr(GetParam(), &max_error);
  std::printf("swizzle %s P_s %d %s %s: PSNR %.2f dB, max |error| %.2e\n",
              GetParam().setup().name.c_str(), GetParam().plane_scale,
              GetParam().precision == PlanePrecision::kU8 ? "u8" : "f32",
              GetParam().filter == PlaneFilter::kNearest ? "nearest" : "bilinear", p, max_error);
  EXPECT_GE(p, 60.0);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GlG2lfSwizzle,
    ::testing::Values(SwizzleCase{cloud, 1, -1.0f, PlanePrecision::kU8, PlaneFilter::kNearest},
                      SwizzleCase{cloud, 1, -1.0f, PlanePrecision::kU8, PlaneFilter::kBilinear},
                      SwizzleCase{cloud, 2, 1.0f, PlanePrecision::kF32, PlaneFilter::kNearest},
                      SwizzleCase{cloud, 2, 1.0f, PlanePrecision::kF32, PlaneFilter::kBilinear},
                      SwizzleCase{tabletop, 2, 0.0f, PlanePrecision::kU8, PlaneFilter::kNearest},
                      SwizzleCase{tabletop, 2, 0.0f, PlanePrecision::kU8, PlaneFilter::kBilinear},
                      SwizzleCase{tabletop, 1, -1.0f, PlanePrecision::kF32, PlaneFilter::kNearest},
                      SwizzleCase{tabletop, 1, -1.0f, PlanePrecision::kF32, PlaneFilter::kBilinear}));

// Several views per invocation share the per-plane factors: the quilt stays the CPU's on f32
// planes whatever the grouping, a view count that is not a multiple included (the cloud has 9
// views), with the views x planes table and without (bilinear by hand). Bit for bit on Mesa
// llvmpipe; NVIDIA's compiler fuses the weights' products into FMAs, which moved the last bits
// (an H200: 1.8e-7 nearest, 3.4e-6 bilinear), so the bound is float rounding, a thousandth of
// a u8 step: a wrong grouping (a view's factors or shift taken from its neighbour) errs by the
// scene's contrast.
TEST(GlG2lfSwizzleViews, EveryGroupingOfViewsGivesTheCpuQuilt) {
  for (const PlaneFilter filter : {PlaneFilter::kNearest, PlaneFilter::kBilinear})
    for (const int views : {1, 2, 4, 8, 16}) {
      double max_error = 1.0;
      for (const bool table : {false, true}) {
        SwizzleOptions options;
        options.views_per_invocation = views;
        options.factor_table = table;
        options.hardware_bilinear = false;  // the CPU's weights
        swizzle_psnr(SwizzleCase{cloud, 2, 1.0f, PlanePrecision::kF32, filter}, &max_error, options);
        EXPECT_LE(max_error, 1e-5) << views << " views per invocation, "
                                  << (filter == PlaneFilter::kNearest ? "nearest" : "bilinear")
                                  << (table ? ", views x planes table" : ", no table");
      }
    }
}

// The texture unit's bilinear filter (its own weights: 8 bits of fraction on NVIDIA) against
// the CPU's float weights, on the CPU's planes: within the swizzle tests' 60 dB, not exact.
TEST(GlG2lfSwizzleHardwareBilinear, StaysWithinTheSwizzleToleranceOfTheCpuFilter) {
  SwizzleOptions options;
  options.hardware_bilinear = true;
  for (const SwizzleCase& c : {SwizzleCase{cloud, 2, 1.0f, PlanePrecision::kF32, PlaneFilter::kBilinear},
                               SwizzleCase{cloud, 1, -1.0f, PlanePrecision::kU8, PlaneFilter::kBilinear},
                               SwizzleCase{tabletop, 2, 0.0f, PlanePrecision::kU8, PlaneFilter::kBilinear},
                               SwizzleCase{tabletop, 1, -1.0f, PlanePrecision::kF32, PlaneFilter::kBilinear}}) {
    double max_error = 0.0;
    const double p = swizzle_psnr(c, &max_error, options);
    std::printf("swizzle, texture unit bilinear, %s P_s %d %s: PSNR %.2f dB, max |error| %.2e\n",
                c.setup().name.c_str(), c.plane_scale, c.precision == PlanePrecision::kU8 ? "u8" : "f32", p, max_error);
    EXPECT_GE(p, 60.0);
    EXPECT_GT(max_error, 0.0) << "the unit's weights are not the CPU's: an exact match means it was not used";
  }
}

// ---- Stage 1: depth binning ----

// Gaussians on a few exact depths (a grid of equal z per layer) and some outside the reference
// frustum: ties and the frustum test are what a GPU binning could get wrong.
const TestScene& ties() {
  static const TestScene s = [] {
    TestScene s;
    s.name = "ties";
    for (int layer = 0; layer < 5; ++layer)
      for (int i = 0; i < 40; ++i)
        render::testing::add_gaussian(s.scene, {float(i % 8) * 0.3f - 1.2f, float(i / 8) * 0.3f - 0.6f, 3.0f + float(layer)},
                                      {0.05f, 0.05f, 0.05f}, 0.8f, {0.5f, 0.2f, 0.1f});
    for (int i = 0; i < 30; ++i)  // beside, behind and in front of the near plane
      render::testing::add_gaussian(s.scene, {30.0f, 0.0f, 4.0f}, {0.05f, 0.05f, 0.05f}, 0.8f, {0.1f, 0.2f, 0.3f});
    render::testing::add_gaussian(s.scene, {0.0f, 0.0f, -1.0f}, {0.05f, 0.05f, 0.05f}, 0.8f, {0.1f, 0.2f, 0.3f});
    const auto base = render::make_look_at_camera({0, 0, 0}, {0, 0, 3.5f}, {0, 1, 0}, 0.6f, 32, 24);
    s.geometry = render::make_quilt_geometry(base, 3.5f, 40.0f, 5);
    s.layout = render::make_quilt_layout(s.geometry, 5, 1);
    return s;
  }();
  return s;
}

// The three-points fixture (tests/data/scenes), framed from its front.
const TestScene& three_points() {
  static const TestScene s = [] {
    TestScene s;
    s.name = "three-points";
    s.scene = scene::load_gaussian_scene(test::fixture_scene("three-points.ply"));
    const auto base = render::make_look_at_camera({0, 0, -4}, {0, 0, 0}, {0, -1, 0}, 0.7f, 32, 24);
    s.geometry = render::make_quilt_geometry(base, 4.0f, 40.0f, 5);
    s.layout = render::make_quilt_layout(s.geometry, 5, 1);
    return s;
  }();
  return s;
}

struct BinningCase {
  const TestScene& (*setup)();
  int chunks;
  ChunkBinning binning;
  float d_shift;
};

class GlG2lfBinning : public ::testing::TestWithParam<BinningCase> {};

TEST_P(GlG2lfBinning, SameChunksAndPlaneDepthsAsTheCpu) {
  const BinningCase& c = GetParam();
  const TestScene& s = c.setup();
  HeadlessContext& ctx = context();
  render::G2lfOptions o;
  o.d_shift = c.d_shift;
  const render::ReferenceCamera ref = render::reference_camera(o, s.geometry);
  const render::DepthChunks cpu = render::bin_by_depth(s.scene, s.geometry, ref, c.chunks, c.binning);

  const GlScene scene(s.scene, ctx.info());
  GlPlaneTable table(c.chunks);
  GlDepthBinning binning;
  GlRadixSort sort;
  Buffer keys(4), values(4), layers(4);
  // The sort over the binned Gaussians only (its first pass drops the others; the default) and
  // over all N give the same chunks.
  for (const bool binned_only : {false, true}) {
    SCOPED_TRACE(binned_only ? "sort over the binned Gaussians" : "sort over all N");
    binning.run(scene, ref, c.chunks, c.binning, sort, keys, values, layers, table, nullptr, binned_only);

    const PlaneTableHeader header = table.read_header();
    const std::vector<PlaneTableEntry> entries = table.read_entries();
    const auto sorted = values.download_as<uint32_t>(s.scene.size());
    const auto layer_of = layers.download_as<uint32_t>(header.splats_binned);
    size_t cpu_binned = 0;
    for (const auto& m : cpu.members) cpu_binned += m.size();
    ASSERT_EQ(header.splats_binned, cpu_binned);
    ASSERT_EQ(header.plane_count, cpu.members.size());
    EXPECT_EQ(entries.back().begin, header.splats_binned);
    for (size_t k = 0; k < cpu.members.size(); ++k) {
      // Bit-exact depths: the same float operations as the CPU.
      EXPECT_EQ(entries[k].depth, cpu.plane_depth[k]) << "plane " << k;
      std::vector<uint32_t> members(sorted.begin() + entries[k].begin, sorted.begin() + entries[k + 1].begin);
      std::sort(members.begin(), members.end());
      EXPECT_EQ(members, cpu.members[k]) << "plane " << k;
      for (uint32_t i = entries[k].begin; i < entries[k + 1].begin; ++i) ASSERT_EQ(layer_of[i], k) << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GlG2lfBinning,
    ::testing::Values(BinningCase{cloud, 64, ChunkBinning::kQuantile, -1.0f},
                      BinningCase{cloud, 64, ChunkBinning::kMixed, -1.0f},
                      BinningCase{cloud, 7, ChunkBinning::kMixed, 0.5f},
                      BinningCase{cloud, 1, ChunkBinning::kQuantile, -1.0f},
                      BinningCase{cloud, 1, ChunkBinning::kMixed, -1.0f},
                      BinningCase{cloud, 2, ChunkBinning::kMixed, -1.0f},
                      BinningCase{cloud, 4096, ChunkBinning::kQuantile, 0.0f},
                      BinningCase{cloud, 4096, ChunkBinning::kMixed, 0.0f},
                      BinningCase{tabletop, 64, ChunkBinning::kQuantile, 0.0f},
                      BinningCase{tabletop, 512, ChunkBinning::kMixed, -1.0f},
                      BinningCase{ties, 12, ChunkBinning::kQuantile, -1.0f},
                      BinningCase{ties, 12, ChunkBinning::kMixed, -1.0f},
                      BinningCase{three_points, 4, ChunkBinning::kMixed, -1.0f},
                      BinningCase{three_points, 8, ChunkBinning::kQuantile, -1.0f}));

// ---- The whole renderer against render::render_quilt_g2lf ----

struct RendererCase {
  const TestScene& (*setup)();
  int chunks;
  ChunkBinning binning;
  PlaneFilter filter;
  int plane_scale;
  PlanePrecision precision;
  float d_shift;
  bool adaptive_filter = true;
  PlaneRaster raster = PlaneRaster::kLayered;
  RasterPath path = RasterPath::kHardware;
};

std::string describe(const RendererCase& c) {
  return fmt::format("{} N={} {} {} P_s={} {} {} {} D_shift={}{}", c.setup().name, c.chunks,
                     c.binning == ChunkBinning::kMixed ? "mixed" : "quantile",
                     c.filter == PlaneFilter::kNearest ? "nearest" : "bilinear", c.plane_scale,
                     c.precision == PlanePrecision::kU8 ? "u8" : "f32", plane_raster_name(c.raster), raster_path_name(c.path), c.d_shift,
                     c.adaptive_filter ? "" : " constant filter");
}

render::G2lfOptions g2lf_options(const RendererCase& c) {
  render::G2lfOptions o;
  o.chunks = c.chunks;
  o.binning = c.binning;
  o.filter = c.filter;
  o.plane_scale = c.plane_scale;
  o.precision = c.precision;
  o.d_shift = c.d_shift;
  o.adaptive_filter = c.adaptive_filter;
  return o;
}

class GlG2lfRendering : public ::testing::TestWithParam<RendererCase> {};

TEST_P(GlG2lfRendering, MatchesTheCpuG2lfQuilt) {
  const RendererCase& c = GetParam();
  const TestScene& s = c.setup();
  HeadlessContext& ctx = context();
  GlG2lfOptions options;
  options.g2lf = g2lf_options(c);
  options.gpu_timers = true;
  options.plane_raster = c.raster;
  options.raster = c.path;
  render::RasterSettings settings;
  settings.background = s.background;
  render::G2lfStats cpu_stats;
  const ImageF cpu = render::render_quilt_g2lf(s.scene, s.geometry, s.layout, options.g2lf, settings, &cpu_stats);

  const GlScene scene(s.scene, ctx.info());
  GlG2lfRenderer renderer(scene, ctx.info());
  const Texture quilt = make_quilt_texture(s.layout, GL_RGBA32F);
  renderer.render_quilt(s.geometry, s.layout, options, settings, quilt);
  const ImageF gl = read_image_top_down(quilt);
  const double p = render::psnr(gl, cpu);
  std::printf("G2LF %s: PSNR GL vs CPU %.2f dB (%d planes)\n", describe(c).c_str(), p, renderer.stats().planes);
  EXPECT_GE(p, 40.0);
  EXPECT_GT(scene_pixel_fraction(cpu, s), 0.01) << "the quilt must show the scene";
  EXPECT_EQ(renderer.stats().planes, cpu_stats.planes);
  EXPECT_EQ(renderer.stats().gaussians_in_frustum, cpu_stats.gaussians_in_frustum);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GlG2lfRendering,
    ::testing::Values(
        RendererCase{cloud, 64, ChunkBinning::kQuantile, PlaneFilter::kNearest, 1, PlanePrecision::kU8, -1.0f},
        RendererCase{cloud, 64, ChunkBinning::kMixed, PlaneFilter::kBilinear, 2, PlanePrecision::kF32, 1.0f},
        RendererCase{cloud, 16, ChunkBinning::kMixed, PlaneFilter::kNearest, 2, PlanePrecision::kU8, 0.0f},
        RendererCase{cloud, 32, ChunkBinning::kQuantile, PlaneFilter::kBilinear, 1, PlanePrecision::kF32, -1.0f},
        RendererCase{tabletop, 64, ChunkBinning::kMixed, PlaneFilter::kBilinear, 1, PlanePrecision::kU8, -1.0f},
        RendererCase{tabletop, 32, ChunkBinning::kQuantile, PlaneFilter::kBilinear, 2, PlanePrecision::kU8, 0.5f},
        RendererCase{tabletop, 64, ChunkBinning::kQuantile, PlaneFilter::kNearest, 1, PlanePrecision::kF32, -1.0f},
        RendererCase{tabletop, 24, ChunkBinning::kMixed, PlaneFilter::kNearest, 2, PlanePrecision::kF32, 0.0f},
        RendererCase{tabletop, 24, ChunkBinning::kMixed, PlaneFilter::kNearest, 1, PlanePrecision::kU8, -1.0f, false},
        RendererCase{three_points, 4, ChunkBinning::kMixed, PlaneFilter::kBilinear, 1, PlanePrecision::kU8, -1.0f},
        RendererCase{tabletop, 2, ChunkBinning::kQuantile, PlaneFilter::kNearest, 1, PlanePrecision::kU8, -1.0f},
        RendererCase{cloud, 1, ChunkBinning::kMixed, PlaneFilter::kBilinear, 1, PlanePrecision::kU8, -1.0f},
        // The batched RGBA8 fallback (the budget's), as before the layered RGBA16F planes.
        RendererCase{cloud, 64, ChunkBinning::kQuantile, PlaneFilter::kNearest, 1, PlanePrecision::kU8, -1.0f, true,
                     PlaneRaster::kBatched},
        RendererCase{tabletop, 64, ChunkBinning::kMixed, PlaneFilter::kBilinear, 1, PlanePrecision::kU8, -1.0f, true,
                     PlaneRaster::kBatched},
        RendererCase{tabletop, 24, ChunkBinning::kMixed, PlaneFilter::kNearest, 1, PlanePrecision::kU8, -1.0f, false,
                     PlaneRaster::kBatched},
        // The compute tile rasterizer's planes (--raster compute): RGBA8 for u8, RGBA32F for f32.
        RendererCase{cloud, 64, ChunkBinning::kQuantile, PlaneFilter::kNearest, 1, PlanePrecision::kU8, -1.0f, true,
                     PlaneRaster::kLayered, RasterPath::kCompute},
        RendererCase{cloud, 64, ChunkBinning::kMixed, PlaneFilter::kBilinear, 2, PlanePrecision::kF32, 1.0f, true,
                     PlaneRaster::kLayered, RasterPath::kCompute},
        RendererCase{tabletop, 64, ChunkBinning::kMixed, PlaneFilter::kBilinear, 1, PlanePrecision::kU8, -1.0f, true,
                     PlaneRaster::kLayered, RasterPath::kCompute},
        RendererCase{tabletop, 24, ChunkBinning::kMixed, PlaneFilter::kNearest, 2, PlanePrecision::kF32, 0.0f, false,
                     PlaneRaster::kLayered, RasterPath::kCompute},
        RendererCase{three_points, 4, ChunkBinning::kMixed, PlaneFilter::kBilinear, 1, PlanePrecision::kU8, -1.0f, true,
                     PlaneRaster::kLayered, RasterPath::kCompute},
        RendererCase{tabletop, 2, ChunkBinning::kQuantile, PlaneFilter::kNearest, 1, PlanePrecision::kU8, -1.0f, true,
                     PlaneRaster::kLayered, RasterPath::kCompute}));

// ---- The planes themselves against the CPU's f32 planes ----

// PSNR (peak 1) and max |error| over C and T of the first `count` planes.
struct PlaneError {
  double psnr = 0, max_error = 0;
};

PlaneError compare_planes(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0, max_error = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = double(a[i]) - double(b[i]);
    sum += d * d;
    max_error = std::max(max_error, std::fabs(d));
  }
  const double mse = sum / double(std::max<size_t>(a.size(), 1));
  return {mse > 0 ? 10.0 * std::log10(1.0 / mse) : INFINITY, max_error};
}

// The GL planes as the CPU lays them out ([plane][row top-down][col][rgbT]), the first `count`.
std::vector<float> read_planes_top_down(const GlPlanes& planes, int count) {
  const size_t layer = size_t(planes.width) * size_t(planes.height) * 4;
  std::vector<float> all(layer * size_t(planes.max_planes));
  glGetTextureImage(planes.texels.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(all.size() * sizeof(float)), all.data());
  std::vector<float> out(layer * size_t(count));
  const size_t row = size_t(planes.width) * 4;
  for (int k = 0; k < count; ++k)
    for (int r = 0; r < planes.height; ++r)
      std::copy_n(all.begin() + std::ptrdiff_t(layer * size_t(k) + row * size_t(planes.height - 1 - r)), row,
                  out.begin() + std::ptrdiff_t(layer * size_t(k) + row * size_t(r)));
  return out;
}

std::vector<float> cpu_planes_as_float(const render::SweepingPlanes& planes) {
  if (planes.precision == PlanePrecision::kF32) return planes.texels_f32;
  std::vector<float> out(planes.texels_u8.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = float(planes.texels_u8[i]) / 255.0f;
  return out;
}

struct PlaneVariant {
  std::string name;
  PlanePrecision precision;
  PlaneRaster raster;
  std::optional<PlaneFormat> format;
};

// Every way of drawing the planes against the CPU's f32 planes (the reference all of them
// round): the old batched RGBA8 path, the layered RGBA16F planes that replace it, RGBA8 blended
// in place, RGBA32F; and the CPU's own u8 planes, the rounding the u8 paths cannot beat. The
// quilts likewise against the CPU's f32 quilt. docs/gpu.md "Planes" lists the figures.
TEST(GlG2lfPlanes, EachRasterAgainstTheCpuFloatPlanes) {
  HeadlessContext& ctx = context();
  for (const TestScene* s : {&tabletop(), &cloud()}) {
    GlG2lfOptions options;
    options.g2lf.chunks = 32;
    options.gpu_timers = true;
    render::RasterSettings settings;
    settings.background = s->background;
    render::G2lfOptions f32_options = options.g2lf;
    f32_options.precision = PlanePrecision::kF32;
    const render::ReferenceCamera ref = render::reference_camera(f32_options, s->geometry);
    const render::DepthChunks chunks = render::bin_by_depth(s->scene, s->geometry, ref, 32, f32_options.binning);
    render::RasterSettings plane_settings;
    plane_settings.dilation_px2 = render::adaptive_filter_variance(s->geometry, ref, 1);
    const std::vector<float> cpu_f32 = render::render_sweeping_planes(s->scene, s->geometry, ref, chunks,
                                                                      PlanePrecision::kF32, plane_settings).texels_f32;
    const PlaneError cpu_u8 = compare_planes(
        cpu_planes_as_float(render::render_sweeping_planes(s->scene, s->geometry, ref, chunks, PlanePrecision::kU8,
                                                           plane_settings)),
        cpu_f32);
    const ImageF cpu_quilt = render::render_quilt_g2lf(s->scene, s->geometry, s->layout, f32_options, settings);
    render::G2lfOptions u8_options = f32_options;
    u8_options.precision = PlanePrecision::kU8;
    const double cpu_u8_quilt =
        render::psnr(render::render_quilt_g2lf(s->scene, s->geometry, s->layout, u8_options, settings), cpu_quilt);
    std::printf("%s: CPU u8 planes vs CPU f32: PSNR %.2f dB, max |error| %.2e; quilt vs CPU f32: %.2f dB\n",
                s->name.c_str(), cpu_u8.psnr, cpu_u8.max_error, cpu_u8_quilt);

    const GlScene scene(s->scene, ctx.info());
    GlG2lfRenderer renderer(scene, ctx.info());
    const Texture quilt = make_quilt_texture(s->layout, GL_RGBA32F);
    std::map<std::string, PlaneError> planes;
    for (const PlaneVariant& v :
         {PlaneVariant{"batched RGBA8", PlanePrecision::kU8, PlaneRaster::kBatched, std::nullopt},
          PlaneVariant{"layered RGBA16F", PlanePrecision::kU8, PlaneRaster::kLayered, std::nullopt},
          PlaneVariant{"layered RGBA8", PlanePrecision::kU8, PlaneRaster::kLayered, PlaneFormat::kRgba8},
          PlaneVariant{"layered RGBA32F", PlanePrecision::kF32, PlaneRaster::kLayered, std::nullopt}}) {
      options.g2lf.precision = v.precision;
      options.plane_raster = v.raster;
      options.plane_format = v.format;
      renderer.render_quilt(s->geometry, s->layout, options, settings, quilt);
      ASSERT_EQ(size_t(renderer.stats().planes), chunks.members.size());
      ASSERT_EQ(renderer.stats().plane_raster, v.raster) << v.name;
      const PlaneError e = compare_planes(read_planes_top_down(renderer.planes(), renderer.stats().planes), cpu_f32);
      const double q = render::psnr(read_image_top_down(quilt), cpu_quilt);
      std::printf("%s: %s planes vs CPU f32: PSNR %.2f dB, max |error| %.2e; quilt vs CPU f32: %.2f dB\n",
                  s->name.c_str(), v.name.c_str(), e.psnr, e.max_error, q);
      planes[v.name] = e;
      EXPECT_GE(q, 40.0) << v.name;  // the renderer tests' tolerance
    }
    // RGBA16F planes drawn in one pass are no further from the float planes than the batched
    // RGBA8 ones they replace, on average (PSNR); a texel may be: 16F rounds C at every blend
    // step (an 11-bit mantissa: increments below half a step near C = 1 are lost), measured up
    // to 2.1 8-bit steps on the tabletop, so the bound is 3 steps. Blending in RGBA8 is worse
    // than both (why it is not the default).
    EXPECT_GE(planes["layered RGBA16F"].psnr, planes["batched RGBA8"].psnr) << s->name;
    EXPECT_LE(planes["layered RGBA16F"].max_error, 3.0 / 255.0) << s->name;
    EXPECT_LT(planes["layered RGBA8"].psnr, planes["layered RGBA16F"].psnr) << s->name;
    EXPECT_GE(planes["layered RGBA32F"].psnr, planes["layered RGBA16F"].psnr) << s->name;
  }
}

// The compute tile rasterizer's planes (--raster compute) against the CPU's own planes of the
// same precision: f32 planes in RGBA32F equal the CPU's to float rounding, u8 planes in RGBA8
// (summed in float, rounded once, as the CPU stores them) to at most one 8-bit step where a sum
// lands next to a rounding boundary; the planes in use only, the rest stay empty (0, 0, 0, 1).
TEST(GlG2lfPlanes, ComputePlanesEqualTheCpuPlanes) {
  HeadlessContext& ctx = context();
  for (const TestScene* s : {&tabletop(), &cloud()}) {
    for (PlanePrecision precision : {PlanePrecision::kF32, PlanePrecision::kU8}) {
      // Hot (plane, tile) slots split into parts at the default threshold and forced at 16 keys.
      for (const uint32_t split_keys : {kTileSplatSplitKeys, 16u}) {
        GlG2lfOptions options;
        options.g2lf.chunks = 32;
        options.g2lf.precision = precision;
        options.gpu_timers = true;
        options.raster = RasterPath::kCompute;
        options.compute_split_keys = split_keys;
        render::RasterSettings settings;
        settings.background = s->background;
        const render::ReferenceCamera ref = render::reference_camera(options.g2lf, s->geometry);
        const render::DepthChunks chunks = render::bin_by_depth(s->scene, s->geometry, ref, 32, options.g2lf.binning);
        render::RasterSettings plane_settings;
        plane_settings.dilation_px2 = render::adaptive_filter_variance(s->geometry, ref, 1);
        const std::vector<float> cpu = cpu_planes_as_float(
            render::render_sweeping_planes(s->scene, s->geometry, ref, chunks, precision, plane_settings));
        const GlScene scene(s->scene, ctx.info());
        GlG2lfRenderer renderer(scene, ctx.info());
        const Texture quilt = make_quilt_texture(s->layout, GL_RGBA32F);
        renderer.render_quilt(s->geometry, s->layout, options, settings, quilt);
        ASSERT_EQ(size_t(renderer.stats().planes), chunks.members.size());
        const GlPlanes& planes = renderer.planes();
        EXPECT_EQ(planes.format, precision == PlanePrecision::kU8 ? PlaneFormat::kRgba8 : PlaneFormat::kRgba32f);
        const PlaneError e = compare_planes(read_planes_top_down(planes, renderer.stats().planes), cpu);
        const double q = render::psnr(read_image_top_down(quilt),
                                      render::render_quilt_g2lf(s->scene, s->geometry, s->layout, options.g2lf, settings));
        std::printf("%s: compute %s planes (split keys %u) vs CPU %s planes: PSNR %.2f dB, max |error| %.2e; "
                    "quilt %.2f dB\n",
                    s->name.c_str(), plane_format_name(planes.format), split_keys,
                    precision == PlanePrecision::kU8 ? "u8" : "f32", e.psnr, e.max_error, q);
        EXPECT_LE(e.max_error, precision == PlanePrecision::kU8 ? 1.0 / 255.0 + 1e-6 : 1e-4) << s->name;
        EXPECT_GE(e.psnr, 60.0) << s->name;
        EXPECT_GE(q, 40.0) << s->name;
      }
    }
  }
}

// The memory check of --raster compute counts its key buffers (GlSplatTileRaster::plane_path_bytes,
// keys at kComputePlaneKeysPerGaussian a Gaussian) instead of the raster's accumulation layers: a
// budget that holds the planes and the binning's buffers (what it counted before) is refused, and the frame's keys
// stay within the estimate on the test scene.
TEST(GlG2lfPlanes, TheComputeMemoryCheckCountsTheKeyBuffers) {
  const TestScene& s = tabletop();
  HeadlessContext& ctx = context();
  GlG2lfOptions options;
  options.g2lf.chunks = 32;
  options.raster = RasterPath::kCompute;
  const size_t n = s.scene.size();
  const size_t binning = n * (sizeof(SplatRecord) + 5 * sizeof(uint32_t));
  const size_t tiles = size_t((s.geometry.base.width + 15) / 16) * size_t((s.geometry.base.height + 15) / 16);
  EXPECT_EQ(g2lf_other_bytes(options, s.geometry, n),
            binning + GlSplatTileRaster::plane_path_bytes(n, 32 * tiles, n * kComputePlaneKeysPerGaussian));
  EXPECT_GT(g2lf_other_bytes(options, s.geometry, n), binning + n * kComputePlaneKeysPerGaussian * 16);
  // What the check counted before the key buffers: the planes, the binning, the raster's batch lists.
  options.memory_budget_bytes = g2lf_plane_array_bytes(options, s.geometry) + binning + n * 2 * sizeof(uint32_t);
  EXPECT_THROW(check_g2lf_fits(options, s.geometry, n, ctx.info(), std::nullopt), InputError);
  options.memory_budget_bytes = 0;
  const GlScene scene(s.scene, ctx.info());
  GlG2lfRenderer renderer(scene, ctx.info());
  const Texture quilt = make_quilt_texture(s.layout, GL_RGBA32F);
  renderer.render_quilt(s.geometry, s.layout, options, {}, quilt);
  const uint32_t keys = renderer.stats().compute_keys;
  std::printf("[ keys ] %u (plane, tile) keys for %zu Gaussians: %.2f a Gaussian\n", keys, n, double(keys) / double(n));
  EXPECT_GT(keys, 0u);
  EXPECT_LE(keys, n * kComputePlaneKeysPerGaussian);
}

// u8-precision planes drawn layered are RGBA16F, twice RGBA8's bytes: a budget that holds only
// the RGBA8 ones falls back to the batched path (and the refusal names the options otherwise).
TEST(GlG2lfPlanes, LayeredRgba16fBeyondTheBudgetFallsBackToBatchedRgba8) {
  const TestScene& s = tabletop();
  HeadlessContext& ctx = context();
  GlG2lfOptions options;
  options.g2lf.chunks = 24;
  options.gpu_timers = true;
  // One accumulation layer (a real frame's 64 MiB are a small part of its planes; these planes
  // are small).
  options.accumulation_budget_bytes = 1;
  GlG2lfOptions batched = options;
  batched.plane_raster = PlaneRaster::kBatched;
  const size_t layered_bytes = g2lf_plane_array_bytes(options, s.geometry) + g2lf_other_bytes(options, s.geometry, s.scene.size());
  const size_t batched_bytes = g2lf_plane_array_bytes(batched, s.geometry) + g2lf_other_bytes(batched, s.geometry, s.scene.size());
  ASSERT_LT(batched_bytes, layered_bytes);
  EXPECT_EQ(g2lf_fitting_options(options, s.geometry, s.scene.size(), (long long)layered_bytes).plane_raster,
            PlaneRaster::kLayered);
  EXPECT_EQ(g2lf_fitting_options(options, s.geometry, s.scene.size(), std::nullopt).plane_raster, PlaneRaster::kLayered)
      << "no budget known (llvmpipe): layered";
  options.memory_budget_bytes = batched_bytes;
  const GlScene scene(s.scene, ctx.info());
  GlG2lfRenderer renderer(scene, ctx.info());
  const Texture quilt = make_quilt_texture(s.layout, GL_RGBA32F);
  renderer.render_quilt(s.geometry, s.layout, options, {}, quilt);
  EXPECT_EQ(renderer.stats().plane_raster, PlaneRaster::kBatched);
  EXPECT_EQ(renderer.stats().plane_format, PlaneFormat::kRgba8);
  EXPECT_EQ(renderer.stats().planes, 23);
  options.memory_budget_bytes = layered_bytes;
  renderer.render_quilt(s.geometry, s.layout, options, {}, quilt);
  EXPECT_EQ(renderer.stats().plane_raster, PlaneRaster::kLayered);
  EXPECT_EQ(renderer.stats().plane_format, PlaneFormat::kRgba16f);
  options.memory_budget_bytes = batched_bytes - 1;
  EXPECT_THROW(renderer.render_quilt(s.geometry, s.layout, options, {}, quilt), InputError);
}

TEST(GlG2lfRenderer, HalfFloatPlanesStayCloseToTheCpuFloatPlanes) {
  const TestScene& s = tabletop();
  context();
  GlG2lfOptions options;
  options.g2lf.chunks = 32;
  options.g2lf.precision = PlanePrecision::kF32;
  options.plane_format = PlaneFormat::kRgba16f;
  render::RasterSettings settings;
  settings.background = s.background;
  const ImageF cpu = render::render_quilt_g2lf(s.scene, s.geometry, s.layout, options.g2lf, settings);
  const ImageF gl = render_quilt_g2lf_gl(s.scene, s.geometry, s.layout, options, settings);
  const double p = render::psnr(gl, cpu);
  std::printf("G2LF RGBA16F planes vs CPU f32: PSNR %.2f dB\n", p);
  EXPECT_GE(p, 40.0);
}

TEST(GlG2lfRenderer, BatchesOfAccumulationLayersGiveTheSamePlanes) {
  const TestScene& s = tabletop();
  HeadlessContext& ctx = context();
  const GlScene scene(s.scene, ctx.info());
  GlG2lfRenderer renderer(scene, ctx.info());
  GlG2lfOptions options;
  options.g2lf.chunks = 24;  // 23 planes (mixed)
  options.gpu_timers = true;
  options.plane_raster = PlaneRaster::kBatched;
  render::RasterSettings settings;
  settings.background = s.background;
  const Texture quilt = make_quilt_texture(s.layout, GL_RGBA32F);
  renderer.render_quilt(s.geometry, s.layout, options, settings, quilt);
  const ImageF one_batch = read_image_top_down(quilt);
  ASSERT_EQ(renderer.stats().planes, 23);
  // Five layers of 56x40 RGBA32F: 23 planes in five batches, the last one partly used.
  options.accumulation_budget_bytes = 5 * 56 * 40 * 16;
  ASSERT_EQ(plane_batch_layers(options.format(), 24, 56, 40, options.accumulation_budget_bytes), 5);
  renderer.render_quilt(s.geometry, s.layout, options, settings, quilt);
  const ImageF five_batches = read_image_top_down(quilt);
  EXPECT_EQ(five_batches.pixels, one_batch.pixels);
  EXPECT_GT(scene_pixel_fraction(one_batch, s), 0.05);
}

TEST(GlG2lfRenderer, NothingInTheReferenceFrustumGivesTheBackground) {
  const TestScene& s = cloud();
  HeadlessContext& ctx = context();
  scene::GaussianScene behind;  // every Gaussian behind the cameras
  for (int i = 0; i < 50; ++i)
    render::testing::add_gaussian(behind, {0.1f * float(i % 7), 0.0f, -2.0f - 0.1f * float(i)},
                                  {0.1f, 0.1f, 0.1f}, 0.9f, {1.0f, 1.0f, 1.0f});
  const GlScene scene(behind, ctx.info());
  GlG2lfRenderer renderer(scene, ctx.info());
  GlG2lfOptions options;
  options.gpu_timers = true;
  render::RasterSettings settings;
  settings.background = {0.25f, 0.5f, 0.75f};
  const Texture quilt = make_quilt_texture(s.layout, GL_RGBA32F);
  renderer.render_quilt(s.geometry, s.layout, options, settings, quilt);
  EXPECT_EQ(renderer.stats().planes, 0);
  EXPECT_EQ(renderer.stats().gaussians_in_frustum, 0u);
  const ImageF gl = read_image_top_down(quilt);
  const ImageF cpu = render::render_quilt_g2lf(behind, s.geometry, s.layout, options.g2lf, settings);
  EXPECT_EQ(gl.pixels, cpu.pixels);
  EXPECT_EQ(gl.at(5, 5, 2), 0.75f);
}

TEST(GlG2lfRenderer, RefusesPlanesBeyondTheMemoryBudgetNamingTheOptions) {
  const TestScene& s = cloud();
  HeadlessContext& ctx = context();
  const GlScene scene(s.scene, ctx.info());
  GlG2lfRenderer renderer(scene, ctx.info());
  GlG2lfOptions options;
  options.g2lf.chunks = 64;
  options.g2lf.plane_scale = 2;
  // 64 planes of 128x96 RGBA8 = 3 MiB: a 2 MiB budget cannot hold them. One float
  // accumulation layer (192 KiB).
  options.memory_budget_bytes = size_t(2) << 20;
  options.accumulation_budget_bytes = size_t(256) << 10;
  const Texture quilt = make_quilt_texture(s.layout);
  try {
    renderer.render_quilt(s.geometry, s.layout, options, {}, quilt);
    FAIL() << "planes beyond the budget were allocated";
  } catch (const InputError& e) {
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find("--chunks"), std::string::npos) << what;
    EXPECT_NE(what.find("--plane-scale"), std::string::npos) << what;
    EXPECT_NE(what.find("--precision"), std::string::npos) << what;
    EXPECT_NE(what.find("MiB"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line";
  }
  // Fewer chunks fit the same budget.
  options.g2lf.chunks = 16;
  EXPECT_NO_THROW(renderer.render_quilt(s.geometry, s.layout, options, {}, quilt));
}

TEST(GlG2lfRenderer, RefusesMoreChunksThanArrayLayers) {
  const TestScene& s = cloud();
  const HeadlessContext& ctx = context();
  GlG2lfOptions options;
  options.g2lf.chunks = 4096;
  if (ctx.info().max_array_layers >= options.g2lf.chunks) GTEST_SKIP() << "this GPU has 4096 layers";
  EXPECT_THROW(check_g2lf_fits(options, s.geometry, s.scene.size(), ctx.info(), std::nullopt), InputError);
}

TEST(GlG2lfRenderer, RefusesOptionsTheCpuRefuses) {
  const TestScene& s = cloud();
  HeadlessContext& ctx = context();
  const GlScene scene(s.scene, ctx.info());
  GlG2lfRenderer renderer(scene, ctx.info());
  GlG2lfOptions options;
  options.g2lf.d_shift = 100.0f;  // beyond D_forward
  const Texture quilt = make_quilt_texture(s.layout);
  EXPECT_THROW(renderer.render_quilt(s.geometry, s.layout, options, {}, quilt), InputError);
}

}  // namespace
}  // namespace lfd::gpu
