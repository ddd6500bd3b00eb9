// The cover layer in a simulated photograph (docs/display-model.md, "The cover layer"): through a 3
// cm acrylic block a camera 30 degrees to the side sees, at each panel point, the view fraction the
// refracted ray predicts (seen_fraction_through_cover), not the one the straight line to the camera
// would. The simulator traces rays from the camera forward through Snell's law; the prediction
// solves the ray from the panel point backward: two independent paths to one relation.
#include <cmath>

#include <gtest/gtest.h>

#include "display/cover_rays.hpp"
#include "display/fraction_panel.hpp"
#include "display/lens_relations.hpp"
#include "sim/simulator.hpp"
#include "simulator_test_support.hpp"

namespace lfd::sim {
namespace {

double wrapped(double x) { return x - std::round(x); }

TEST(SimulatorThroughCover, APhotoFromTheSideShowsTheRefractedViewFractions) {
  display::DisplayCalibration d = testing::small_display();  // 16" Gen2 optics
  d.cover = {0.03, 1.49};
  const DisplaySimulator sim{display::LensModel(d)};
  const display::LensModel& lens = sim.lens();
  const ImageF cos_panel = display::view_fraction_panel(lens, false), sin_panel = display::view_fraction_panel(lens, true);
  const ImageF white(d.screen_w, d.screen_h, 3, 1.0f);
  const Eigen::Vector3d eye(0.26, 0.0, 0.45);
  const PhysicalCamera cam(CameraIntrinsics::from_fov(45.0, 400, 300),
                           CameraPose{eye, {0, 0, 0}, {0, 1, 0}});
  CaptureEffects fx;
  fx.exposure = 0.3;
  const ImageF photo_cos = sim.capture(cos_panel, cam, fx);
  const ImageF photo_sin = sim.capture(sin_panel, cam, fx);
  const ImageF photo_white = sim.capture(white, cam, fx);
  // The fraction seen around panel point p, found in the photo where p's light leaves the block.
  auto seen_at = [&](const Eigen::Vector3d& p) {
    const display::Point3 e = display::cover_exit_point({p.x(), p.y(), 0.0}, {eye.x(), eye.y(), eye.z()}, d.cover);
    Eigen::Vector2d px;
    EXPECT_TRUE(cam.project(Eigen::Vector3d(e.x, e.y, e.z), px));
    return testing::seen_fraction_around(photo_cos, photo_sin, photo_white, int(px.x()), int(px.y()));
  };
  for (double x : {-0.3, 0.0, 0.3}) {
    const Eigen::Vector3d p(x * d.width_m(), 0.1 * d.height_m(), 0.0);
    const Eigen::Vector3d to_eye = eye - p;
    const double refracted = display::seen_fraction_through_cover(to_eye.x(), to_eye.y(), to_eye.z(),
                                                         d.cover, lens.line_tilt(), d.view_cone_deg);
    const double straight =
        display::seen_fraction(to_eye.x(), to_eye.y(), to_eye.z(), lens.line_tilt(), d.view_cone_deg);
    const double measured = seen_at(p);
    std::printf("x %.2f W: measured %.4f, refracted %.4f, straight line %.4f\n", x,
                measured - std::floor(measured), refracted - std::floor(refracted),
                straight - std::floor(straight));
    EXPECT_NEAR(wrapped(measured - refracted), 0.0, 0.006);
    // And the straight line is clearly the worse prediction (0.012-0.038 off here).
    EXPECT_LT(std::abs(wrapped(measured - refracted)), 0.5 * std::abs(wrapped(measured - straight)));
  }
}

}  // namespace
}  // namespace lfd::sim
