// The interlacing shader against the CPU reference interlacer (interlace::interlace): within 1/255
// on >= 99.9 % of subpixels (docs/gpu.md "The interlacing shader") on every calibration fixture
// and the bundled Go and 8K templates, both blends, overscan, invert, a correction field, BGR
// panels, Gen3 cell patterns and fringe; each case through both stages (the fragment pass and
// the compute pass), which must also agree with each other bit for bit.
#include "gpu/panel/gl_interlacer.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "gpu/gl/gl_context.hpp"
#include "interlace/interlacer.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

using display::CorrectionField;
using display::DisplayCalibration;
using display::LensModel;
using interlace::InterlaceOptions;
using interlace::ViewBlend;
using render::QuiltLayout;

// Tiles of 72 x 56 texels in a C x R grid with a margin (viewPortion < 1), content aspect
// `aspect` (not the display's, so the aspect fit matters).
QuiltLayout quilt_layout(int cols, int rows, double aspect) {
  QuiltLayout q;
  q.cols = cols;
  q.rows = rows;
  q.views = cols * rows;
  q.aspect = aspect;
  q.width = cols * 72 + 3;
  q.height = rows * 56 + 2;
  return q;
}

// Smooth inside each tile (so bilinear lookups are well defined) but different in every view and
// channel, with strong gradients: a wrong tile, a wrong texel or a bleed across a tile edge shows.
ImageF varying_quilt(const QuiltLayout& q) {
  ImageF img(q.width, q.height, 3, 0.f);
  const int tw = q.tile_width(), th = q.tile_height();
  const double two_pi = 2 * std::numbers::pi;
  for (int k = 0; k < q.views; ++k)
    for (int y = 0; y < th; ++y)
      for (int x = 0; x < tw; ++x)
        for (int c = 0; c < 3; ++c) {
          const double s = double(x) / tw, t = double(y) / th;
          const double value =
              0.5 + 0.45 * std::sin(two_pi * (s * (1 + k % 3) + 0.37 * k + 0.21 * c)) *
                        std::cos(two_pi * (t * (1 + (k / 3) % 2) + 0.13 * k - 0.3 * c));
          img.at(q.tile_x(k) + x, q.tile_y_top_down(k) + y, c) = float(value);
        }
  return img;
}

// A real unit's lens on a panel 1/`shrink` the size (same DPI, so the same subpixels per lens).
DisplayCalibration shrunk(DisplayCalibration c, int shrink) {
  c.screen_w /= shrink;
  c.screen_h /= shrink;
  return c;
}

// A field of +-0.15 lens periods on the solver's default 8 x 8 grid, bent in both directions.
CorrectionField some_correction() {
  const int n = 8;
  std::vector<double> coefficients;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      coefficients.push_back(0.15 * std::sin(0.5 * i + 0.3 * j) * std::cos(0.35 * j - 0.2 * i));
  return CorrectionField(n, n, coefficients);
}

struct Agreement {
  double max_difference = 0;
  double fraction_within = 0;  // of subpixels within 1/255
  size_t outside = 0;          // subpixels further apart
  size_t outside_not_ties = 0; // of those, ones whose lens phase is no boundary tie
};

// A subpixel whose lens phase lies within `tolerance` of a view boundary (a multiple of 1 / V,
// 0 and 1 included: the wrap) may show either neighbour in single precision (lens_view.glsl).
bool boundary_tie(const LensModel& lens, int x, int row, int c, int views, double tolerance) {
  const double a = lens.phase(lens.subpixel_uv(x, row, c));
  const double t = (a - std::floor(a)) * views;
  return std::abs(t - std::round(t)) <= tolerance * views;
}

// `lens` and `views`: check that every subpixel further apart than 1/255 is a boundary tie.
Agreement compare(const ImageF& gpu, const ImageF& cpu, const LensModel* lens = nullptr, int views = 0,
                  double tolerance = kLensViewTolerance) {
  EXPECT_EQ(gpu.width, cpu.width);
  EXPECT_EQ(gpu.height, cpu.height);
  Agreement a;
  size_t within = 0;
  for (size_t i = 0; i < cpu.pixels.size(); ++i) {
    const double d = std::abs(double(gpu.pixels[i]) - cpu.pixels[i]);
    a.max_difference = std::max(a.max_difference, d);
    within += d <= 1.0 / 255;
    if (d <= 1.0 / 255) continue;
    ++a.outside;
    const int c = int(i % 3), x = int(i / 3 % size_t(cpu.width)), row = int(i / 3 / size_t(cpu.width));
    if (lens && !boundary_tie(*lens, x, row, c, views, tolerance)) ++a.outside_not_ties;
  }
  a.fraction_within = double(within) / double(cpu.pixels.size());
  return a;
}

std::string describe(const InterlaceOptions& o) {
  return std::string(o.blend == ViewBlend::kLinear ? "linear" : "nearest") +
         (o.overscan ? " overscan" : "") + (o.invert_views ? " invert" : "");
}

// Interlaces on both sides with every blend x {fit, overscan, invert}; asserts the tolerance
// and prints the figures (docs/rendering.md quotes them).
void expect_shader_matches_cpu(const std::string& name, const DisplayCalibration& display,
                               const QuiltLayout& q, const CorrectionField& correction = {}) {
  const LensModel lens(display, correction);
  const ImageF quilt = varying_quilt(q);
  for (const ViewBlend blend : {ViewBlend::kNearest, ViewBlend::kLinear})
    for (int variant = 0; variant < 3; ++variant) {
      InterlaceOptions o;
      o.blend = blend;
      o.overscan = variant == 1;
      o.invert_views = variant == 2;
      const ImageF cpu = interlace::interlace(quilt, q, lens, o);
      const ImageF fragment = interlace_on_gpu(quilt, q, lens, o, InterlacePass::kFragment);
      for (const InterlacePass pass : {InterlacePass::kFragment, InterlacePass::kCompute}) {
        const bool compute = pass == InterlacePass::kCompute;
        const ImageF gpu = compute ? interlace_on_gpu(quilt, q, lens, o, pass) : fragment;
        const Agreement a = compare(gpu, cpu, &lens, q.views);
        const std::string what = describe(o) + (compute ? " (compute)" : "");
        std::printf("  %-38s %4dx%-4d %-24s max |GL - CPU| %.2e  within 1/255: %.5f %% (%zu ties)\n",
                    name.c_str(), display.screen_w, display.screen_h, what.c_str(), a.max_difference,
                    100 * a.fraction_within, a.outside);
        EXPECT_GE(a.fraction_within, 0.999) << name << " " << what;
        // Stricter than the tolerance: with the phase's large part reduced in double on the CPU
        // (lens_view.glsl), a subpixel shows another view than on the CPU only where its phase
        // lies within kLensViewTolerance of a view boundary (the phase in plain float32 would
        // flip ~1e-4 of them anywhere). A correction field is sampled from a grid, which moves
        // view boundaries by up to kCorrectionGridTolerancePeriods more.
        if (correction.empty()) {
          EXPECT_EQ(a.outside_not_ties, 0u) << name << " " << what;
        }
        // One function (interlace_pixel.glsl) in both stages: the same floats.
        if (compute) {
          EXPECT_EQ(0, std::memcmp(gpu.pixels.data(), fragment.pixels.data(), gpu.pixels.size() * sizeof(float)))
              << name << " " << what << ": the compute pass differs from the fragment pass";
        }
      }
    }
}

class GlInterlacerOnFixture : public testing::TestWithParam<std::filesystem::path> {};

TEST_P(GlInterlacerOnFixture, MatchesTheCpuInterlacer) {
  HeadlessContext context;
  const DisplayCalibration full = display::read_visual_json(GetParam());
  const DisplayCalibration small = shrunk(full, full.screen_w > 2000 ? 8 : 4);
  const double display_aspect = double(small.screen_w) / small.screen_h;
  expect_shader_matches_cpu(GetParam().stem().stem().string(), small,
                            quilt_layout(5, 9, 0.8 * display_aspect));
}

// OpenGL ES 3.1 (docs/arm.md): the same passes assembled for GLSL ES 3.10 (gpu::glsl_es_source)
// on an ES context, both stages, every fixture, held to the same tolerance.
TEST_P(GlInterlacerOnFixture, MatchesTheCpuInterlacerOnOpenGlEs) {
  HeadlessContext context(GlRequest::kEs);
  ASSERT_TRUE(context.info().es) << context.info().summary();
  const DisplayCalibration full = display::read_visual_json(GetParam());
  const DisplayCalibration small = shrunk(full, full.screen_w > 2000 ? 8 : 4);
  const double display_aspect = double(small.screen_w) / small.screen_h;
  expect_shader_matches_cpu(GetParam().stem().stem().string() + " (ES)", small,
                            quilt_layout(5, 9, 0.8 * display_aspect));
}

// The calibration fixtures (Gen1, Gen2, the Portrait, the 16" Gen3 template with cells) and the
// bundled templates of the Go and the 8K panels (32" Gen2, 32" portrait Gen3 with cells).
std::vector<std::filesystem::path> calibrations() {
  std::vector<std::filesystem::path> files = test::fixture_calibrations();
  for (const char* name : {"go", "32in-gen2", "32in-portrait-gen3"})
    files.push_back(test::project_data() / "displays" / (std::string(name) + ".visual.json"));
  return files;
}

INSTANTIATE_TEST_SUITE_P(EveryCalibration, GlInterlacerOnFixture,
                         testing::ValuesIn(calibrations()),
                         [](const testing::TestParamInfo<std::filesystem::path>& info) {
                           std::string name = info.param.stem().stem().string();
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

TEST(GlInterlacer, MatchesWithACorrectionField) {
  HeadlessContext context;
  const DisplayCalibration c =
      shrunk(display::read_visual_json(test::fixture_calibration("LKG-2K-04409.visual.json")), 4);
  expect_shader_matches_cpu("LKG-2K-04409 + correction", c, quilt_layout(8, 6, 1.25),
                            some_correction());
}

TEST(GlInterlacer, MatchesOnBgrPanelsWithFringeAndEitherViewOrder) {
  HeadlessContext context;
  DisplayCalibration c =
      shrunk(display::read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json")), 8);
  c.flip_subp = true;  // no fixture has a BGR panel
  c.fringe = 0.1;
  expect_shader_matches_cpu("LKG-APW92011 flipSubp fringe", c, quilt_layout(5, 9, 1.2));
  c.inv_view = false;
  c.flip_image_x = true;  // negates the tilt
  c.fringe = -0.2;
  expect_shader_matches_cpu("LKG-APW92011 flipSubp !invView flipX", c, quilt_layout(5, 9, 1.2));
}

TEST(GlInterlacer, MatchesEveryGen3CellPattern) {
  HeadlessContext context;
  DisplayCalibration c = shrunk(
      display::read_visual_json(test::fixture_calibration("template-16in-portrait-gen3.visual.json")), 8);
  ASSERT_TRUE(c.has_cells());
  // Four cells so pattern 3 (period 4 in j) shows all of them.
  c.subpixel_cells.push_back({-0.3, 0.1, 0.1, -0.2, 0.3, 0.3});
  c.subpixel_cells.push_back({0.2, 0.3, -0.1, -0.3, 0.0, 0.1});
  for (int mode = 1; mode <= 4; ++mode) {
    c.cell_pattern_mode = mode;
    expect_shader_matches_cpu("gen3 template, cell pattern " + std::to_string(mode), c,
                              quilt_layout(8, 6, 0.5), mode == 3 ? some_correction() : CorrectionField{});
  }
}

TEST(GlInterlacer, MatchesAFullSizePanel) {
  HeadlessContext context;
  const DisplayCalibration c =
      display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  const LensModel lens(c, some_correction());
  const QuiltLayout q = quilt_layout(8, 6, 0.75);
  const ImageF quilt = varying_quilt(q);
  InterlaceOptions o;
  o.blend = ViewBlend::kLinear;
  const Agreement a = compare(interlace_on_gpu(quilt, q, lens, o), interlace::interlace(quilt, q, lens, o));
  std::printf("  %-38s %4dx%-4d %-24s max |GL - CPU| %.2e  within 1/255: %.5f %%\n",
              "LKG-PORT-portrait + correction", c.screen_w, c.screen_h, "linear",
              a.max_difference, 100 * a.fraction_within);
  EXPECT_GE(a.fraction_within, 0.999);
}

TEST(GlInterlacer, Rgba8PanelTextureHoldsTheCpuPanelsBytes) {
  // The texture-to-texture path a frame uses (quilt texture in, RGBA8 panel out), compared
  // with the 8-bit image the CPU path writes, through either stage.
  HeadlessContext context;
  const DisplayCalibration c =
      shrunk(display::read_visual_json(test::fixture_calibration("gen1-hid-00297.visual.json")), 4);
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(5, 9, 1.6);
  const ImageF quilt = varying_quilt(q);
  const Image8 cpu = to_uint8(interlace::interlace(quilt, q, lens));
  for (const InterlacePass pass : {InterlacePass::kFragment, InterlacePass::kCompute}) {
    GlInterlacer interlacer(lens, q, {}, pass);
    const Texture quilt_texture = texture_from_image(quilt);
    Texture panel(GL_RGBA8, c.screen_w, c.screen_h);
    interlacer.interlace(quilt_texture, panel);
    const Image8 gpu = to_uint8(image_from_texture(panel));
    size_t equal = 0;
    for (size_t i = 0; i < cpu.pixels.size(); ++i) equal += std::abs(gpu.pixels[i] - cpu.pixels[i]) <= 1;
    EXPECT_GE(double(equal) / double(cpu.pixels.size()), 0.999) << (pass == InterlacePass::kCompute ? "compute" : "fragment");
  }
}

TEST(GlInterlacer, TheCorrectionGridInterpolatesTheFieldWithinItsTolerance) {
  HeadlessContext context;
  const DisplayCalibration c =
      shrunk(display::read_visual_json(test::fixture_calibration("LKG-2K-04409.visual.json")), 4);
  const QuiltLayout q = quilt_layout(5, 9, 1.6);
  const GlInterlacer plain(LensModel(c), q);
  EXPECT_EQ(plain.correction_grid().width(), 2);
  const CorrectionField field = some_correction();
  const GlInterlacer corrected(LensModel(c, field), q);
  const Texture& grid = corrected.correction_grid();
  const int gw = grid.width(), gh = grid.height();
  ASSERT_LE(std::max(gw, gh), kMaxCorrectionGridPoints);
  const std::vector<float> texels = read_texture_rgba(grid);  // red = w
  const auto w = [&](int i, int j) { return double(texels[(size_t(j) * gw + i) * 4]); };
  // The shader's bilinear lookup, at points between the grid points, against the B-spline.
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const double u = std::fmod(k * 0.61803398875, 1.0), v = std::fmod(k * 0.7548776662, 1.0);
    const double gx = u * (gw - 1), gy = v * (gh - 1);
    const int i = std::min(int(gx), gw - 2), j = std::min(int(gy), gh - 2);
    const double ax = gx - i, ay = gy - j;
    const double interpolated = (w(i, j) * (1 - ax) + w(i + 1, j) * ax) * (1 - ay) +
                                (w(i, j + 1) * (1 - ax) + w(i + 1, j + 1) * ax) * ay;
    worst = std::max(worst, std::abs(interpolated - field(u, v)));
  }
  std::printf("  correction grid %dx%d, worst interpolation error %.2e periods\n", gw, gh, worst);
  EXPECT_LE(worst, kCorrectionGridTolerancePeriods + 1e-7);  // + float storage of w ~ 0.15
}

TEST(GlInterlacer, AQuiltOrPanelOfTheWrongSizeIsAnInputError) {
  HeadlessContext context;
  const DisplayCalibration c =
      shrunk(display::read_visual_json(test::fixture_calibration("LKG-2K-04409.visual.json")), 8);
  const LensModel lens(c);
  const QuiltLayout q = quilt_layout(5, 9, 1.6);
  for (const InterlacePass pass : {InterlacePass::kFragment, InterlacePass::kCompute}) {
    GlInterlacer interlacer(lens, q, {}, pass);
    Texture panel(GL_RGBA8, c.screen_w, c.screen_h);
    EXPECT_THROW(interlacer.interlace(Texture(GL_RGBA8, q.width - 1, q.height), panel), InputError);
    Texture wrong_panel(GL_RGBA8, c.screen_w, c.screen_h + 1);
    EXPECT_THROW(interlacer.interlace(Texture(GL_RGBA8, q.width, q.height), wrong_panel), InputError);
  }
  EXPECT_THROW(interlace_on_gpu(ImageF(q.width, q.height + 1, 3), q, lens), InputError);
}

}  // namespace
}  // namespace lfd::gpu
