// The GL voxel path (issue #13) against the exact CPU voxel rasterizer and CPU V2LF on real EGL
// contexts (llvmpipe here): one box's transmittance, views whose rays take several octants,
// per-view quilts with supersampling, and V2LF with every option the CPU path has (split
// voxels, the planes' low-pass filter, u8/f32 planes). Small images: llvmpipe runs on the CPU.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "gpu/gl_context.hpp"
#include "gpu/gl_v2lf.hpp"
#include "gpu/gl_voxel_scene.hpp"
#include "gpu/gl_voxel_views.hpp"
#include "render/image_metrics.hpp"
#include "../voxel/voxel_test_scenes.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_quilt.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::gpu {
namespace {

HeadlessContext& context() {
  static HeadlessContext c;
  return c;
}

ImageF rgb_of(const render::RasterImage& image) {
  ImageF f(image.width, image.height, 3);
  f.pixels = image.rgb;
  return f;
}

ImageF transmittance_of(const render::RasterImage& image) {
  ImageF f(image.width, image.height, 1);
  f.pixels = image.transmittance;
  return f;
}

// A generated scene (shell, ground, objects; SH degree 1) and a 5-view quilt of 96x72 views.
struct Fixture {
  voxel::VoxelScene scene;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture f;
    voxel::VoxelGeneratorOptions o;
    o.detail_level = 6;
    o.sh_degree = 1;
    f.scene = voxel::generate_voxel_scene(o);
    const render::Camera base =
        render::make_look_at_camera({0, -1.5f, -5.5f}, {0, 0.5f, 0}, {0, -1, 0}, 0.8f, 96, 72);
    f.geometry = render::make_quilt_geometry(base, std::sqrt(2.0f * 2.0f + 6.0f * 6.0f), 40.0f, 5);
    f.layout = render::make_quilt_layout(f.geometry, 5, 1);
    return f;
  }();
  return f;
}

TEST(GlVoxel, OneBoxTransmitsExpOfDensityTimesChord) {
  context().make_current();
  voxel::VoxelScene s = voxel::testing::empty_scene();
  const float sigma = 0.02f;
  voxel::testing::add_voxel(s, {0, 0, 0}, 0, voxel::testing::raw_density_for(sigma), {0.8f, 0.4f, 0.2f});
  // Head-on through the middle of the unit root box: the chord is 1.
  const render::Camera camera = voxel::testing::camera_through({0.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 0.0f});
  render::QuiltGeometry geometry = render::make_quilt_geometry(camera, 3.0f, 10.0f, 1);
  const render::RasterImage gl = render_voxel_view_gl(s, geometry, 0);
  const int centre = (camera.height / 2) * camera.width + camera.width / 2;
  const float expected_t = std::exp(-100.0f * sigma * 1.0f);
  EXPECT_NEAR(gl.transmittance[size_t(centre)], expected_t, 1e-4f);
  EXPECT_NEAR(gl.rgb[3 * size_t(centre)], 0.8f * (1.0f - expected_t), 1e-4f);
}

TEST(GlVoxel, ViewsMatchTheCpuRasterizerInEveryOctant) {
  context().make_current();
  const Fixture& f = fixture();
  // Rays of the base view, and of a camera inside the shell looking along an axis, whose rays
  // take four octants (x and y of both signs).
  const render::Camera inside = render::make_look_at_camera({0.3f, 0.6f, -1.0f}, {0.3f, 0.6f, 3.0f}, {0, -1, 0}, 1.2f, 80, 64);
  for (const render::Camera& camera : {f.geometry.base, inside}) {
    const uint32_t octants = octants_in_view(camera);
    const render::RasterImage cpu = voxel::rasterize_voxels(f.scene, camera);
    const GlVoxelScene gl_scene(f.scene, query_gl_info("test"));
    GlVoxelViews views(gl_scene);
    const render::RasterImage gl = views.render_view(camera, {});
    const double rgb_db = render::psnr(rgb_of(gl), rgb_of(cpu));
    const double t_db = render::psnr(transmittance_of(gl), transmittance_of(cpu));
    std::printf("octants 0x%02x: rgb %.1f dB, transmittance %.1f dB\n", octants, rgb_db, t_db);
    EXPECT_GT(rgb_db, 50.0);
    EXPECT_GT(t_db, 50.0);
  }
  EXPECT_GE(__builtin_popcount(octants_in_view(inside)), 4);
}

TEST(GlVoxel, PerViewQuiltMatchesTheCpu) {
  context().make_current();
  const Fixture& f = fixture();
  const ImageF cpu = voxel::render_voxel_quilt_per_view(f.scene, f.geometry, f.layout);
  const ImageF gl = render_voxel_quilt_per_view_gl(f.scene, f.geometry, f.layout);
  const double db = render::psnr(gl, cpu);
  std::printf("per-view voxel quilt: GL vs CPU %.1f dB\n", db);
  EXPECT_GT(db, 50.0);
}

TEST(GlVoxel, V2lfMatchesTheCpuWithEveryOption) {
  context().make_current();
  const Fixture& f = fixture();
  struct Case {
    const char* name;
    render::PlanePrecision precision;
    render::PlaneFilter filter;
    int chunks, plane_scale, split_levels;
    bool lowpass;
  };
  for (const Case& c : {Case{"u8 nearest, 16 chunks, split, low-pass", render::PlanePrecision::kU8,
                             render::PlaneFilter::kNearest, 16, 1, 1, true},
                        Case{"f32 bilinear, 32 chunks, Ps 2, no split, no low-pass", render::PlanePrecision::kF32,
                             render::PlaneFilter::kBilinear, 32, 2, 0, false}}) {
    GlV2lfOptions options;
    options.v2lf.planes.chunks = c.chunks;
    options.v2lf.planes.plane_scale = c.plane_scale;
    options.v2lf.planes.precision = c.precision;
    options.v2lf.planes.filter = c.filter;
    options.v2lf.planes.adaptive_filter = c.lowpass;
    options.v2lf.split_levels = c.split_levels;
    voxel::V2lfStats cpu_stats;
    const ImageF cpu =
        voxel::render_quilt_v2lf(f.scene, f.geometry, f.layout, options.v2lf, f.scene.background, &cpu_stats);
    GlV2lfStats stats;
    const ImageF gl = render_quilt_v2lf_gl(f.scene, f.geometry, f.layout, options, f.scene.background, &stats);
    const double db = render::psnr(gl, cpu);
    std::printf("V2LF %s: GL vs CPU %.1f dB (%d planes, %zu voxels binned, %zu split)\n", c.name, db, stats.planes,
                stats.voxels_binned, stats.voxels_split);
    EXPECT_GT(db, 45.0) << c.name;
    EXPECT_EQ(stats.planes, cpu_stats.planes);  // the CPU's binning, split voxels included
    EXPECT_EQ(stats.voxels_binned, cpu_stats.voxels_binned);
    if (c.split_levels > 0) {
      EXPECT_GT(stats.voxels_split, 0u);
    }
  }
}

}  // namespace
}  // namespace lfd::gpu
