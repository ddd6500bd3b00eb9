// The factory's CPU renderers: each renders what the call it wraps renders, bit for bit, and
// the options, scenes and calls they refuse.
#include <stdexcept>

#include <gtest/gtest.h>

#include "lightfield/renderer_factory.hpp"
#include "light_field_test_scenes.hpp"
#include "render/g2lf.hpp"
#include "render/per_view_quilt.hpp"
#include "util/error.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_quilt.hpp"

namespace lfd::lightfield {
namespace {

void expect_same_pixels(const ImageF& a, const ImageF& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.channels, b.channels);
  EXPECT_TRUE(a.pixels == b.pixels);
}

ImageF rgb(const render::RasterImage& image) {
  ImageF f(image.width, image.height, 3);
  f.pixels = image.rgb;
  return f;
}

// The renderer's quilt and view 1 of `scene`.
struct Rendered {
  ImageF quilt, view;
  QuiltStats stats;
  std::string name;
};
Rendered render_with(const RendererOptions& options, const scene::Scene& scene) {
  const auto renderer = make_renderer(options, scene.kind());
  renderer->set_scene(scene);
  const render::QuiltGeometry geometry = test_geometry(scene);
  Rendered r;
  r.stats = renderer->render_quilt(geometry, test_layout(geometry));
  r.quilt = renderer->read_quilt();
  r.view = renderer->render_view(geometry, 1);
  r.name = renderer->name();
  return r;
}

TEST(CpuRenderers, GaussiansPerViewAreRenderQuiltPerView) {
  const RendererOptions o = test_options(Backend::kCpu, Method::kPerView);
  const Rendered r = render_with(o, test_gaussians());
  const render::QuiltGeometry g = test_geometry(test_gaussians());
  EXPECT_EQ(r.name, "cpu");
  expect_same_pixels(r.quilt, render::render_quilt_per_view(test_gaussians().gaussians(), g, test_layout(g),
                                                            o.raster_settings()));
  expect_same_pixels(r.view, rgb(render::render_view(test_gaussians().gaussians(), g, 1, o.raster_settings())));
  EXPECT_EQ(r.stats.planes, 0);
}

TEST(CpuRenderers, GaussiansSweepingPlanesAreG2lf) {
  const RendererOptions o = test_options(Backend::kCpu, Method::kSweepingPlanes);
  const Rendered r = render_with(o, test_gaussians());
  const render::QuiltGeometry g = test_geometry(test_gaussians());
  render::G2lfStats stats;
  expect_same_pixels(r.quilt, render::render_quilt_g2lf(test_gaussians().gaussians(), g, test_layout(g), o.planes,
                                                        o.raster_settings(), &stats));
  expect_same_pixels(r.view, rgb(render::render_view(test_gaussians().gaussians(), g, 1, o.raster_settings())));
  EXPECT_EQ(r.stats.planes, stats.planes);
  EXPECT_EQ(r.stats.plane_bytes, stats.plane_bytes);
  EXPECT_EQ(r.stats.binned, stats.gaussians_in_frustum);
  EXPECT_GT(r.stats.planes, 1);
}

TEST(CpuRenderers, VoxelsPerViewAreRenderVoxelQuiltPerView) {
  const RendererOptions o = test_options(Backend::kCpu, Method::kPerView);
  const Rendered r = render_with(o, test_voxels());
  const render::QuiltGeometry g = test_geometry(test_voxels());
  const scene::VoxelScene& scene = test_voxels().voxels();
  expect_same_pixels(r.quilt, voxel::render_voxel_quilt_per_view(scene, g, test_layout(g), o.voxel_settings()));
  expect_same_pixels(r.view, rgb(voxel::render_voxel_view(scene, g, 1, o.voxel_settings())));
}

TEST(CpuRenderers, VoxelsSweepingPlanesAreV2lf) {
  RendererOptions o = test_options(Backend::kCpu, Method::kSweepingPlanes);
  o.split_levels = 1;
  o.background.reset();  // the scene's own
  const Rendered r = render_with(o, test_voxels());
  const render::QuiltGeometry g = test_geometry(test_voxels());
  const scene::VoxelScene& scene = test_voxels().voxels();
  voxel::V2lfStats stats;
  expect_same_pixels(r.quilt, voxel::render_quilt_v2lf(scene, g, test_layout(g), o.v2lf(), scene.background, &stats));
  expect_same_pixels(r.view, rgb(voxel::render_voxel_view(scene, g, 1, o.voxel_settings())));
  EXPECT_EQ(r.stats.planes, stats.planes);
  EXPECT_EQ(r.stats.binned, stats.voxels_binned);
  EXPECT_EQ(r.stats.voxels_split, stats.voxels_split);
}

TEST(RendererFactory, ChecksTheOptionsAndTheCallsMade) {
  RendererOptions f16 = test_options(Backend::kCpu, Method::kSweepingPlanes);
  f16.gl.plane_format = gpu::PlaneFormat::kRgba16f;
  EXPECT_THROW(make_renderer(f16, scene::SceneKind::kGaussians), InputError);
  RendererOptions chunks = test_options(Backend::kCpu, Method::kSweepingPlanes);
  chunks.planes.chunks = 0;
  EXPECT_THROW(make_renderer(chunks, scene::SceneKind::kVoxels), InputError);

  const RendererOptions o = test_options(Backend::kCpu, Method::kPerView);
  const auto renderer = make_renderer(o, scene::SceneKind::kGaussians);
  EXPECT_THROW(renderer->set_scene(test_voxels()), std::logic_error);
  const render::QuiltGeometry g = test_geometry(test_gaussians());
  EXPECT_THROW(renderer->render_quilt(g, test_layout(g)), std::logic_error);  // no scene yet
  EXPECT_THROW(renderer->set_options(test_options(Backend::kCpu, Method::kSweepingPlanes)), std::logic_error);
  RendererOptions other = o;
  other.background = glm::vec3(1.0f);
  renderer->set_options(other);
  EXPECT_EQ(renderer->options().background, other.background);
  EXPECT_THROW(make_gl_renderer(o, scene::SceneKind::kGaussians, nullptr), std::logic_error);
}

TEST(Scene, KnowsItsKindSizeAndFraming) {
  EXPECT_EQ(test_gaussians().kind(), scene::SceneKind::kGaussians);
  EXPECT_STREQ(test_gaussians().primitives(), "Gaussians");
  EXPECT_EQ(test_gaussians().size(), test_gaussians().gaussians().size());
  EXPECT_EQ(test_voxels().kind(), scene::SceneKind::kVoxels);
  EXPECT_STREQ(test_voxels().primitives(), "voxels");
  EXPECT_THROW(test_voxels().gaussians(), std::logic_error);
  EXPECT_NE(test_gaussians().id(), test_voxels().id());
  EXPECT_EQ(scene::scene_kind_of_file(LFD_SOURCE_DIR "/data/scenes/demo.ply"), scene::SceneKind::kGaussians);
  EXPECT_EQ(method_name(Method::kSweepingPlanes, scene::SceneKind::kVoxels), "v2lf");
  EXPECT_EQ(method_name(Method::kSweepingPlanes, scene::SceneKind::kGaussians), "g2lf");
  EXPECT_EQ(method_name(Method::kPerView, scene::SceneKind::kVoxels), "per-view");
}

}  // namespace
}  // namespace lfd::lightfield
