// A scene or planes too large for the GPU: the frame lowers the SH degree (3 -> 2 -> 1 -> 0) and
// the plane precision (RGBA32F -> RGBA8) to the largest that fits, says so, and still refuses
// (one line with the numbers) when even the lowest does not fit. The budgets are injected
// (llvmpipe reports no free memory).
#include <filesystem>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "render/default_camera.hpp"
#include "render/scene_generator.hpp"
#include "tests/support/scene_fixtures.hpp"
#include "util/error.hpp"
#include "viewer/light_field_frame.hpp"

namespace lfd::viewer {
namespace {

scene::GaussianScene test_scene() { return test::generated_gaussians(3000, 3); }

ViewerSettings small_settings() {
  ViewerSettings s;
  s.views = 8;
  s.view_height_px = 64;
  s.g2lf.chunks = 8;
  return s;
}

size_t needed_bytes(size_t gaussians, int sh_degree) {
  return gaussians * (gpu::scene_bytes_per_gaussian(sh_degree) + gpu::per_view_scratch_bytes_per_gaussian());
}

TEST(LightFieldFrameFit, ASceneAboveTheFreeMemoryIsShownAtTheLargestShDegreeThatFits) {
  gpu::HeadlessContext context;
  const scene::GaussianScene scene = test_scene();
  gpu::GlInfo info = context.info();
  info.free_memory_bytes = (long long)needed_bytes(scene.size(), 1);  // degree 2 and 3 do not fit
  LightFieldFrame frame(scene, test::portrait_calibration(), info);
  EXPECT_EQ(frame.scene_sh_degree(), 1);
  EXPECT_NE(frame.scene_fit_notice().find("SH degree 1 (its own: 3)"), std::string::npos)
      << frame.scene_fit_notice();
  frame.render(render::frame_scene(scene), small_settings());
  const ImageF panel = gpu::image_from_texture(frame.panel());
  double sum = 0;
  for (float value : panel.pixels) sum += value;
  EXPECT_GT(sum, 0.0) << "the lowered scene rendered nothing";
}

TEST(LightFieldFrameFit, ASceneThatFitsIsUploadedWhole) {
  gpu::HeadlessContext context;
  LightFieldFrame frame(test_scene(), test::portrait_calibration(), context.info());
  EXPECT_EQ(frame.scene_sh_degree(), 3);
  EXPECT_TRUE(frame.scene_fit_notice().empty());
}

TEST(LightFieldFrameFit, ASceneAboveTheMemoryEvenAtDegreeZeroIsRefusedWithTheNumbers) {
  gpu::HeadlessContext context;
  gpu::GlInfo info = context.info();
  info.free_memory_bytes = (long long)needed_bytes(3000, 0) - 1;
  try {
    LightFieldFrame frame(test_scene(), test::portrait_calibration(), info);
    FAIL() << "a scene above the memory at SH degree 0 was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("3000 Gaussians at SH degree 0"), std::string::npos) << message;
  }
}

TEST(LightFieldFrameFit, Rgba32fPlanesThatDoNotFitFallBackToRgba8) {
  gpu::HeadlessContext context;
  const scene::GaussianScene scene = test_scene();
  ViewerSettings s = small_settings();
  s.g2lf.precision = render::PlanePrecision::kF32;
  const lightfield::ViewPlan plan = plan_frame(test::portrait_calibration(), render::frame_scene(scene), s);
  // u8 planes drawn layered are RGBA16F (half of RGBA32F; RGBA8 with a float accumulation
  // array of one layer here when those do not fit), so u8 needs less than RGBA32F.
  gpu::GlG2lfOptions f32, u8;
  f32.g2lf = u8.g2lf = s.g2lf;
  f32.accumulation_budget_bytes = u8.accumulation_budget_bytes = 1;
  u8.g2lf.precision = render::PlanePrecision::kU8;
  auto need = [&](const gpu::GlG2lfOptions& o) {
    return gpu::g2lf_plane_array_bytes(o, plan.geometry) + gpu::g2lf_other_bytes(o, plan.geometry, scene.size());
  };
  ASSERT_LT(need(u8), need(f32));
  FrameOptions options;
  options.g2lf_memory_budget_bytes = need(u8);
  options.g2lf_accumulation_budget_bytes = 1;
  LightFieldFrame frame(scene, test::portrait_calibration(), context.info(), options);
  frame.render(render::frame_scene(scene), s);
  EXPECT_NE(frame.plane_fit_notice().find("RGBA8"), std::string::npos) << frame.plane_fit_notice();
  // Below the RGBA16F planes, u8 planes fall back to batched RGBA8 (gpu::g2lf_fitting_options);
  // below those too: the RGBA32F refusal, naming the options that lower it.
  gpu::GlG2lfOptions u8_batched = u8;
  u8_batched.plane_raster = gpu::PlaneRaster::kBatched;
  ASSERT_LT(need(u8_batched), need(u8));
  FrameOptions tight;
  tight.g2lf_memory_budget_bytes = need(u8_batched) - 1;
  tight.g2lf_accumulation_budget_bytes = 1;
  LightFieldFrame refused(scene, test::portrait_calibration(), context.info(), tight);
  try {
    refused.render(render::frame_scene(scene), s);
    FAIL() << "planes above the budget were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--chunks"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lfd::viewer
