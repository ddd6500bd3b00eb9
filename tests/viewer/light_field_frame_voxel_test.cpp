// `lfd view` on a sparse-voxel scene: the frame's quilt (V2LF for the G2LF method, else per
// view) is the CPU's for the same plan, and the panel is drawn; the viewer's loader tells the
// two kinds of scene file apart.
#include <filesystem>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "render/image_metrics.hpp"
#include "tests/support/scene_fixtures.hpp"
#include "util/error.hpp"
#include "viewer/light_field_frame.hpp"
#include "scene/scene.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_generator.hpp"
#include "scene/voxel_io.hpp"
#include "voxel/voxel_quilt.hpp"

namespace lfd::viewer {
namespace {

scene::VoxelScene test_scene() {
  voxel::VoxelGeneratorOptions o;
  o.detail_level = 5;
  return voxel::generate_voxel_scene(o);
}

ViewerSettings small_settings(Method method) {
  ViewerSettings s;
  s.method = method;
  s.views = 6;
  s.view_height_px = 48;
  s.g2lf.chunks = 16;
  s.background = glm::vec3(0.1f, 0.2f, 0.3f);
  return s;
}

TEST(LightFieldFrameVoxels, QuiltsAreTheCpusForBothMethods) {
  gpu::HeadlessContext context;
  const scene::VoxelScene scene = test_scene();
  LightFieldFrame frame(scene, test::portrait_calibration(), context.info());
  EXPECT_TRUE(frame.shows_voxels());
  const render::CameraSpec camera = voxel::frame_voxel_scene(scene);
  for (const Method method : {Method::kG2lf, Method::kPerView}) {
    SCOPED_TRACE(method_name(method));
    const ViewerSettings settings = small_settings(method);
    frame.render(camera, settings);
    const lightfield::ViewPlan& plan = frame.plan();
    voxel::V2lfOptions v2lf;
    v2lf.planes = settings.g2lf;
    v2lf.split_levels = 0;
    voxel::VoxelRenderSettings views;
    views.background = settings.background;
    const ImageF cpu = method == Method::kG2lf
                           ? voxel::render_quilt_v2lf(scene, plan.geometry, plan.layout, v2lf, settings.background)
                           : voxel::render_voxel_quilt_per_view(scene, plan.geometry, plan.layout, views);
    const ImageF gl = gpu::read_image_top_down(frame.quilt(), 3);  // RGBA8: within 1/510
    const double db = render::psnr(gl, cpu);
    std::printf("%s: viewer quilt vs CPU %.1f dB\n", method_name(method).c_str(), db);
    EXPECT_GT(db, 40.0);
    const ImageF panel = gpu::read_image_top_down(frame.panel(), 3);
    double sum = 0;
    for (float value : panel.pixels) sum += value;
    EXPECT_GT(sum, 0.0) << "the panel is black";
  }
}

TEST(LightFieldFrameVoxels, TheLoaderTellsVoxelsFromGaussians) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "lfd_viewer_scene_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path voxels = dir / "scene.voxels";
  scene::save_voxel_scene(voxels, test_scene());
  const scene::Scene loaded = scene::load_scene(voxels.string());
  EXPECT_EQ(loaded.kind(), scene::SceneKind::kVoxels);
  EXPECT_EQ(loaded.size(), test_scene().size());
  EXPECT_STREQ(loaded.primitives(), "voxels");
  const scene::Scene gaussians =
      scene::load_scene((std::filesystem::path(LFD_SOURCE_DIR) / "data" / "scenes" / "demo.ply").string());
  EXPECT_EQ(gaussians.kind(), scene::SceneKind::kGaussians);
  EXPECT_STREQ(gaussians.primitives(), "Gaussians");
  EXPECT_THROW(scene::load_scene((dir / "missing.voxels").string()), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lfd::viewer
