// The factory's GL renderers (llvmpipe here): each renders what the gpu/ call it wraps renders,
// and the CPU's image to within the tolerances of tests/gpu; renderers on one device share one
// scene upload; the viewer's extension renders into the caller's texture.
#include <gtest/gtest.h>

#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/voxels/gl_v2lf.hpp"
#include "gpu/voxels/gl_voxel_views.hpp"
#include "lightfield/renderer_factory.hpp"
#include "light_field_test_scenes.hpp"
#include "render/image_metrics.hpp"

namespace lfd::lightfield {
namespace {

// One device per test: a fresh context, as the gpu tests make.
std::shared_ptr<GlDevice> device_or_skip() {
  try {
    return GlDevice::open_headless();
  } catch (const gpu::GlUnavailable& e) {
    return nullptr;
  }
}

#define DEVICE_OR_SKIP(name)                          \
  const auto name = device_or_skip();                 \
  if (!name) GTEST_SKIP() << "no OpenGL 4.5 context"

// The GL renderer's quilt and view 1, and the CPU renderer's of the same options.
struct Pair {
  ImageF gl_quilt, gl_view, cpu_quilt, cpu_view;
};
Pair render_both(RendererOptions options, const scene::Scene& scene, const std::shared_ptr<GlDevice>& device) {
  const render::QuiltGeometry geometry = test_geometry(scene);
  const render::QuiltLayout layout = test_layout(geometry);
  Pair p;
  options.backend = Backend::kGl;
  const auto gl = make_renderer(options, scene.kind(), device);
  EXPECT_EQ(gl->name(), "gl");
  gl->set_scene(scene);
  gl->render_quilt(geometry, layout);
  p.gl_quilt = gl->read_quilt();
  p.gl_view = gl->render_view(geometry, 1);
  options.backend = Backend::kCpu;
  const auto cpu = make_renderer(options, scene.kind());
  cpu->set_scene(scene);
  cpu->render_quilt(geometry, layout);
  p.cpu_quilt = cpu->read_quilt();
  p.cpu_view = cpu->render_view(geometry, 1);
  return p;
}

ImageF rgb(const render::RasterImage& image) {
  ImageF f(image.width, image.height, 3);
  f.pixels = image.rgb;
  return f;
}

// tests/gpu's tolerances against the CPU: >= 40 dB for Gaussians, >= 45 dB for voxels; against
// the gpu/ call it wraps (the same GL code): >= 80 dB.
constexpr double kGaussianDb = 40.0, kVoxelDb = 45.0, kSameCallDb = 80.0;

TEST(GlRenderers, GaussiansPerViewAreGlPerViewRenderer) {
  DEVICE_OR_SKIP(device);
  const RendererOptions o = test_options(Backend::kGl, Method::kPerView);
  const Pair p = render_both(o, test_gaussians(), device);
  EXPECT_GE(render::psnr(p.gl_quilt, p.cpu_quilt), kGaussianDb);
  EXPECT_GE(render::psnr(p.gl_view, p.cpu_view), kGaussianDb);
  const render::QuiltGeometry g = test_geometry(test_gaussians());
  const gpu::GlScene scene(test_gaussians().gaussians(), device->info());
  gpu::GlPerViewRenderer direct(scene);
  EXPECT_GE(render::psnr(p.gl_view, rgb(direct.render_view_image(g.view_camera(1), o.raster_settings()))), kSameCallDb);
}

TEST(GlRenderers, GaussiansSweepingPlanesAreGlG2lf) {
  DEVICE_OR_SKIP(device);
  const RendererOptions o = test_options(Backend::kGl, Method::kSweepingPlanes);
  const Pair p = render_both(o, test_gaussians(), device);
  EXPECT_GE(render::psnr(p.gl_quilt, p.cpu_quilt), kGaussianDb);
  EXPECT_GE(render::psnr(p.gl_view, p.cpu_view), kGaussianDb);
  const render::QuiltGeometry g = test_geometry(test_gaussians());
  const ImageF direct = gpu::render_quilt_g2lf_gl(test_gaussians().gaussians(), g, test_layout(g), o.gl_g2lf(),
                                                  o.raster_settings());
  EXPECT_GE(render::psnr(p.gl_quilt, direct), kSameCallDb);
}

TEST(GlRenderers, VoxelsPerViewAreGlVoxelViews) {
  DEVICE_OR_SKIP(device);
  const RendererOptions o = test_options(Backend::kGl, Method::kPerView);
  const Pair p = render_both(o, test_voxels(), device);
  EXPECT_GE(render::psnr(p.gl_quilt, p.cpu_quilt), kVoxelDb);
  EXPECT_GE(render::psnr(p.gl_view, p.cpu_view), kVoxelDb);
  const render::QuiltGeometry g = test_geometry(test_voxels());
  const ImageF direct =
      gpu::render_voxel_quilt_per_view_gl(test_voxels().voxels(), g, test_layout(g), o.voxel_settings());
  EXPECT_GE(render::psnr(p.gl_quilt, direct), kSameCallDb);
}

TEST(GlRenderers, VoxelsSweepingPlanesAreGlV2lf) {
  DEVICE_OR_SKIP(device);
  RendererOptions o = test_options(Backend::kGl, Method::kSweepingPlanes);
  o.background.reset();  // the scene's own
  const Pair p = render_both(o, test_voxels(), device);
  EXPECT_GE(render::psnr(p.gl_quilt, p.cpu_quilt), kVoxelDb);
  EXPECT_GE(render::psnr(p.gl_view, p.cpu_view), kVoxelDb);
  const render::QuiltGeometry g = test_geometry(test_voxels());
  const ImageF direct = gpu::render_quilt_v2lf_gl(test_voxels().voxels(), g, test_layout(g), o.gl_v2lf(),
                                                  test_voxels().voxels().background);
  EXPECT_GE(render::psnr(p.gl_quilt, direct), kSameCallDb);
}

TEST(GlRenderers, RenderersOnOneDeviceShareTheSceneUploadAndTheQuilt) {
  DEVICE_OR_SKIP(device);
  const auto per_view = make_renderer(test_options(Backend::kGl, Method::kPerView), scene::SceneKind::kGaussians, device);
  const auto g2lf = make_renderer(test_options(Backend::kGl, Method::kSweepingPlanes), scene::SceneKind::kGaussians, device);
  per_view->set_scene(test_gaussians());
  const uint64_t generation = device->scene_generation();
  const size_t bytes = gpu::gpu_bytes_allocated();
  g2lf->set_scene(test_gaussians());
  EXPECT_EQ(device->scene_generation(), generation);  // not uploaded again
  EXPECT_LT(gpu::gpu_bytes_allocated() - bytes, device->gaussians()->bytes());
  EXPECT_EQ(device->gaussians()->size(), test_gaussians().size());
  const render::QuiltGeometry g = test_geometry(test_gaussians());
  g2lf->render_quilt(g, test_layout(g));
  // Another scene replaces the upload; both bind to it.
  const scene::Scene copy = scene::Scene(test_gaussians().gaussians());
  per_view->set_scene(copy);
  EXPECT_NE(device->scene_generation(), generation);
  EXPECT_NO_THROW(g2lf->render_quilt(g, test_layout(g)));
  EXPECT_THROW(per_view->set_scene(test_voxels()), std::logic_error);
}

TEST(GlRenderers, RenderIntoTheCallersTextureOnTheCurrentContext) {
  DEVICE_OR_SKIP(headless);
  const auto device = GlDevice::on_current_context(headless->info());
  const auto renderer =
      make_gl_renderer(test_options(Backend::kGl, Method::kSweepingPlanes), scene::SceneKind::kGaussians, device);
  renderer->set_scene(test_gaussians());
  const render::QuiltGeometry g = test_geometry(test_gaussians());
  const render::QuiltLayout layout = test_layout(g);
  gpu::Texture quilt(GL_RGBA32F, layout.width, layout.height);
  const QuiltStats stats = renderer->render_quilt_into(g, layout, quilt);
  EXPECT_EQ(stats.planes, 16);  // the layers allocated
  EXPECT_GT(stats.plane_bytes, 0u);
  renderer->render_quilt(g, layout);
  EXPECT_GE(render::psnr(gpu::read_image_top_down(quilt, 3), renderer->read_quilt()), kSameCallDb);
}

}  // namespace
}  // namespace lfd::lightfield
