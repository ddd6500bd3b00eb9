// G2LF on the GPU against the CPU reference, stage by stage (render/g2lf.hpp): the swizzle pass
// on the CPU's own planes, the depth binning, and the whole renderer, on real EGL contexts
// (llvmpipe here). Images are small: llvmpipe runs compute shaders on the CPU.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "gpu/gl_context.hpp"
#include "gpu/gl_planes.hpp"
#include "gpu/gl_swizzle.hpp"
#include "render/depth_binning.hpp"
#include "render/g2lf.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "../render/render_test_scenes.hpp"

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
struct Setup {
  std::string name;
  render::GaussianScene scene;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
  glm::vec3 background{0.0f};
};

// Random Gaussians in front of a camera at the origin; 9 views of 64x48 in a 3x3 quilt.
const Setup& cloud() {
  static const Setup s = [] {
    Setup s;
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
const Setup& tabletop() {
  static const Setup s = [] {
    Setup s;
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

render::ReferenceCamera reference_camera(const Setup& s, const render::G2lfOptions& o) {
  const float d_shift = o.d_shift >= 0.0f ? o.d_shift
                                          : render::make_reference_camera(s.geometry, 0.0f, 1).d_forward;
  return render::make_reference_camera(s.geometry, d_shift, o.plane_scale);
}

// Fraction of a tile-covered quilt's pixels that differ from the background: a comparison
// of two empty quilts would prove nothing.
double scene_pixel_fraction(const ImageF& quilt, const Setup& s) {
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
  const Setup& (*setup)();
  int plane_scale;
  float d_shift;
  PlanePrecision precision;
  PlaneFilter filter;
};

double swizzle_psnr(const SwizzleCase& c, double* max_error) {
  context();
  const Setup& s = c.setup();
  render::G2lfOptions o;
  o.chunks = 24;
  o.plane_scale = c.plane_scale;
  o.d_shift = c.d_shift;
  const render::ReferenceCamera ref = reference_camera(s, o);
  const render::DepthChunks chunks = render::bin_by_depth(s.scene, s.geometry, ref, o.chunks, o.binning);
  render::RasterSettings settings;
  settings.dilation_px2 = render::adaptive_filter_variance(s.geometry, ref, o.plane_scale);
  const render::SweepingPlanes planes =
      render::render_sweeping_planes(s.scene, s.geometry, ref, chunks, c.precision, settings);
  ImageF cpu(s.layout.width, s.layout.height, 3, 0.0f);
  render::swizzle_blend(planes, s.geometry, ref, s.layout, c.filter, s.background, cpu);

  const GlPlanes gl_planes = upload_planes(planes);
  const Texture quilt = make_quilt_texture(s.layout, GL_RGBA32F);
  GlSwizzle swizzle;
  swizzle.run(gl_planes, s.geometry, ref, s.layout, c.filter, s.background, quilt);
  const ImageF gl = read_quilt_texture(quilt);
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

}  // namespace
}  // namespace lfd::gpu
