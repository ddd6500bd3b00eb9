// The direct panel pass on the GPU (gpu/panel/gl_direct_panel.hpp) against the CPU's
// (interlace::render_direct_panel) on the same planes of flat-coloured layers: u8 and f32
// planes, nearest and bilinear, invView both ways, overscan, Gen3 cells, fringe; each case
// through both stages (the compute pass over panel tiles and the fragment pass), which must
// agree bit for bit, and the compute pass over more planes than one batch of its tile walk.
#include "gpu/panel/gl_direct_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/panel/shaders/lens_view_io.h"
#include "tests/interlace/flat_layer_planes.hpp"
#include "tests/test_data.hpp"

namespace lfd::gpu {
namespace {

struct Agreement {
  double max_difference = 0;
  double fraction_within = 0;  // of subpixels within 1/255
};

Agreement compare(const ImageF& gpu, const ImageF& cpu) {
  EXPECT_EQ(gpu.width, cpu.width);
  EXPECT_EQ(gpu.height, cpu.height);
  Agreement a;
  size_t within = 0;
  for (size_t i = 0; i < cpu.pixels.size() && i < gpu.pixels.size(); ++i) {
    const double d = std::abs(double(gpu.pixels[i]) - cpu.pixels[i]);
    a.max_difference = std::max(a.max_difference, d);
    within += d <= 1.0 / 255;
  }
  a.fraction_within = double(within) / double(cpu.pixels.size());
  return a;
}

// A sample lands on the other side of a texel boundary (nearest) when the CPU's and the GPU's
// float rounding differ there: a few subpixels on layer edges, so the bar is a fraction.
void expect_gpu_matches_cpu(const std::string& name, const display::LensModel& lens,
                            const test_planes::FlatLayerScene& s) {
  for (const render::PlaneFilter filter : {render::PlaneFilter::kNearest, render::PlaneFilter::kBilinear})
    for (int variant = 0; variant < 3; ++variant) {
      interlace::DirectPanelOptions o;
      o.filter = filter;
      o.background = s.background;
      o.overscan = variant == 1;
      o.invert_views = variant == 2;
      const ImageF cpu = interlace::render_direct_panel(s.planes, s.geometry, s.ref, lens, o);
      const ImageF fragment = direct_panel_on_gpu(s.planes, s.geometry, s.ref, lens, o, false, DirectPanelPass::kFragment);
      const ImageF gpu = direct_panel_on_gpu(s.planes, s.geometry, s.ref, lens, o, false, DirectPanelPass::kCompute);
      const Agreement a = compare(gpu, cpu);
      const std::string what = name + (filter == render::PlaneFilter::kBilinear ? " bilinear" : " nearest") +
                               (o.overscan ? " overscan" : "") + (o.invert_views ? " invert" : "");
      std::printf("  %-44s max |GL - CPU| %.2e  within 1/255: %.4f %%\n", what.c_str(), a.max_difference,
                  100 * a.fraction_within);
      EXPECT_GE(a.fraction_within, 0.999) << what;
      if (filter == render::PlaneFilter::kBilinear) {
        EXPECT_LT(a.max_difference, 0.02) << what;
      }
      // One definition of a ray (direct_panel_rays.glsl) in both stages: the same floats.
      ASSERT_EQ(gpu.pixels.size(), fragment.pixels.size());
      EXPECT_EQ(0, std::memcmp(gpu.pixels.data(), fragment.pixels.data(), gpu.pixels.size() * sizeof(float)))
          << what << ": the compute pass differs from the fragment pass";
    }
}

TEST(GlDirectPanel, MatchesTheCpuDirectPass) {
  HeadlessContext context;
  display::DisplayCalibration c = display::read_visual_json(test::fixture_calibration("LKG-2K-04409.visual.json"));
  c.screen_w /= 8;
  c.screen_h /= 8;
  c.fringe = 0.1;
  const display::LensModel lens(c);
  expect_gpu_matches_cpu("LKG-2K-04409 / 8, f32 planes", lens, test_planes::flat_layer_scene(160, 100, 8));
  expect_gpu_matches_cpu("LKG-2K-04409 / 8, u8 planes", lens,
                         test_planes::flat_layer_scene(160, 100, 8, render::PlanePrecision::kU8));
}

TEST(GlDirectPanel, MatchesTheCpuDirectPassOnGen3Cells) {
  HeadlessContext context;
  display::DisplayCalibration c =
      display::read_visual_json(test::fixture_calibration("template-16in-portrait-gen3.visual.json"));
  c.screen_w /= 8;
  c.screen_h /= 8;
  c.inv_view = false;
  const display::LensModel lens(c);
  expect_gpu_matches_cpu("16in portrait Gen3 / 8, !invView", lens, test_planes::flat_layer_scene(135, 240, 32));
}

// The texture unit's bilinear filter (the renderers' default on the GPU: one fetch instead of
// four) against the CPU's float weights: within the by-hand path's bars, but not exact (an
// exact match would mean the unit's filter was not used).
TEST(GlDirectPanel, HardwareBilinearStaysWithinTheBarsOfTheCpuFilter) {
  HeadlessContext context;
  display::DisplayCalibration c = display::read_visual_json(test::fixture_calibration("LKG-2K-04409.visual.json"));
  c.screen_w /= 8;
  c.screen_h /= 8;
  const display::LensModel lens(c);
  for (const auto precision : {render::PlanePrecision::kF32, render::PlanePrecision::kU8}) {
    const test_planes::FlatLayerScene s = test_planes::flat_layer_scene(160, 100, 8, precision);
    for (const bool invert : {false, true}) {
      interlace::DirectPanelOptions o;
      o.filter = render::PlaneFilter::kBilinear;
      o.background = s.background;
      o.invert_views = invert;
      const ImageF cpu = interlace::render_direct_panel(s.planes, s.geometry, s.ref, lens, o);
      const Agreement a = compare(direct_panel_on_gpu(s.planes, s.geometry, s.ref, lens, o, true), cpu);
      std::printf("  texture unit bilinear, %s planes%s: max |GL - CPU| %.2e  within 1/255: %.4f %%\n",
                  precision == render::PlanePrecision::kU8 ? "u8" : "f32", invert ? ", invert" : "",
                  a.max_difference, 100 * a.fraction_within);
      EXPECT_GE(a.fraction_within, 0.999);
      EXPECT_LT(a.max_difference, 0.02);
      EXPECT_GT(a.max_difference, 0.0) << "the unit's weights are not the CPU's";
    }
  }
}

// `layers` thin layers (transmittance 0.98, so a ray stays open through all 300 of them: 0.98^300
// = 2.3e-3 > 0.5/255) between depths 1.2 and 3.5, bands of three widths, and an opaque layer in
// the left quarter after the first third: rays of some tiles stop early, others not at all.
test_planes::FlatLayerScene many_layer_scene(int width, int height, int views, int layers) {
  test_planes::FlatLayerScene s = test_planes::flat_layer_scene(width, height, views);
  std::vector<float> depths;
  for (int k = 0; k < layers; ++k) depths.push_back(1.2f + 2.3f * float(k) / float(layers - 1));
  const int w = s.ref.camera.width, h = s.ref.camera.height;
  s.planes = render::make_sweeping_planes(s.ref, depths, render::PlanePrecision::kF32, [&](int k) {
    render::RasterImage image;
    image.width = w;
    image.height = h;
    image.rgb.assign(size_t(w) * h * 3, 0.0f);
    image.transmittance.assign(size_t(w) * h, 1.0f);
    const int x0 = (k * 7) % w, x1 = std::min(w, x0 + w / (2 + k % 3));
    const bool wall = k == layers / 3;
    for (int y = 0; y < h; ++y)
      for (int x = wall ? 0 : x0; x < (wall ? w / 4 : x1); ++x) {
        const size_t i = size_t(y) * w + x;
        const float t = wall ? 0.0f : 0.98f;
        image.transmittance[i] = t;
        for (int c = 0; c < 3; ++c) image.rgb[i * 3 + size_t(c)] = (1.0f - t) * float((k + c) % 5) / 4.0f;
      }
    return image;
  });
  return s;
}

// More planes than one batch of the compute pass's tile walk (kDirectPanelPlaneBatch), some tiles
// closing early, a panel whose width is no multiple of the tile.
TEST(GlDirectPanel, TheComputeTilesWalkEveryBatchOfPlanes) {
  HeadlessContext context;
  display::DisplayCalibration c =
      display::read_visual_json(test::fixture_calibration("template-16in-portrait-gen3.visual.json"));
  c.screen_w /= 8;
  c.screen_h /= 8;
  ASSERT_NE(c.screen_w % int(kDirectPanelTileWidth), 0);
  const display::LensModel lens(c);
  const int layers = int(kDirectPanelPlaneBatch) * 2 + 44;
  const test_planes::FlatLayerScene s = many_layer_scene(68, 120, 16, layers);
  for (const render::PlaneFilter filter : {render::PlaneFilter::kNearest, render::PlaneFilter::kBilinear}) {
    interlace::DirectPanelOptions o;
    o.filter = filter;
    o.background = s.background;
    const ImageF cpu = interlace::render_direct_panel(s.planes, s.geometry, s.ref, lens, o);
    const ImageF gpu = direct_panel_on_gpu(s.planes, s.geometry, s.ref, lens, o);
    const Agreement a = compare(gpu, cpu);
    std::printf("  %d planes, compute, %s: max |GL - CPU| %.2e  within 1/255: %.4f %%\n", layers,
                filter == render::PlaneFilter::kBilinear ? "bilinear" : "nearest", a.max_difference,
                100 * a.fraction_within);
    EXPECT_GE(a.fraction_within, 0.999);
    // The plane-major walk (a barrier a plane) reads in another order, not other floats.
    const ImageF plane_major =
        direct_panel_on_gpu(s.planes, s.geometry, s.ref, lens, o, true, DirectPanelPass::kComputePlaneMajor);
    const ImageF batch = direct_panel_on_gpu(s.planes, s.geometry, s.ref, lens, o, true, DirectPanelPass::kCompute);
    ASSERT_EQ(plane_major.pixels.size(), batch.pixels.size());
    EXPECT_EQ(0, std::memcmp(plane_major.pixels.data(), batch.pixels.data(), batch.pixels.size() * sizeof(float)));
  }
}

TEST(GlDirectPanel, APanelTextureOfTheWrongSizeIsAnInputError) {
  HeadlessContext context;
  const display::LensModel lens(display::read_visual_json(test::fixture_calibration("LKG-2K-04409.visual.json")));
  const test_planes::FlatLayerScene s = test_planes::flat_layer_scene(32, 20, 4);
  const GlPlanes planes = upload_planes(s.planes);
  for (const DirectPanelPass stage : {DirectPanelPass::kFragment, DirectPanelPass::kCompute}) {
    GlDirectPanel pass(lens, true, stage);
    Texture panel(GL_RGBA8, 100, 100);
    EXPECT_THROW(pass.run(planes, s.geometry, s.ref, {}, panel), InputError);
  }
}

}  // namespace
}  // namespace lfd::gpu
