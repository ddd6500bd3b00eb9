// Vertical parallax in a simulated photograph (docs/display-model.md, "What a viewer sees: vertical
// parallax of slanted lenses"): a camera in front of the screen sees other views at the top of the
// screen than at the bottom, by what seen_fraction() predicts, because a slanted lens has power
// only across its lines.
#include <cmath>

#include <gtest/gtest.h>

#include "display/fraction_panel.hpp"
#include "display/lens_relations.hpp"
#include "sim/simulator.hpp"
#include "simulator_test_support.hpp"

namespace lfd::sim {
namespace {

double wrapped(double x) { return x - std::round(x); }

TEST(SimulatorVerticalParallax, TopAndBottomOfAPhotoShowTheViewsSeenFractionPredicts) {
  const DisplaySimulator sim{display::LensModel(testing::small_display())};  // 16" Gen2 optics
  const display::LensModel& lens = sim.lens();
  const auto& c = lens.calibration();
  const ImageF cos_panel = display::view_fraction_panel(lens, false), sin_panel = display::view_fraction_panel(lens, true);
  const ImageF white(c.screen_w, c.screen_h, 3, 1.0f);
  // Level with the centre and 0.1 m above it, half a metre away, looking at the centre.
  for (double height : {0.0, 0.1}) {
    SCOPED_TRACE(::testing::Message() << "camera height " << height);
    const Eigen::Vector3d eye(0.0, height, 0.5);
    const PhysicalCamera cam(CameraIntrinsics::from_fov(45.0, 400, 300),
                             CameraPose{eye, {0, 0, 0}, {0, 1, 0}});
    CaptureEffects fx;
    fx.exposure = 0.3;  // a sharp lens magnifies one subpixel 3x: keep it below clipping
    const ImageF photo_cos = sim.capture(cos_panel, cam, fx);
    const ImageF photo_sin = sim.capture(sin_panel, cam, fx);
    const ImageF photo_white = sim.capture(white, cam, fx);
    // The fraction seen around panel point p: the phasor over a patch of the photo.
    auto seen_at = [&](const Eigen::Vector3d& p) {
      Eigen::Vector2d px;
      EXPECT_TRUE(cam.project(p, px));
      return testing::seen_fraction_around(photo_cos, photo_sin, photo_white, int(px.x()), int(px.y()));
    };
    auto predicted_at = [&](const Eigen::Vector3d& p) {
      const Eigen::Vector3d d = eye - p;
      return display::seen_fraction(d.x(), d.y(), d.z(), lens.line_tilt(), c.view_cone_deg);
    };
    const Eigen::Vector3d top(0, 0.4 * c.height_m(), 0), bottom(0, -0.4 * c.height_m(), 0);
    const double measured = wrapped(seen_at(top) - seen_at(bottom));
    const double predicted = predicted_at(top) - predicted_at(bottom);
    // 0.8 H_m line_tilt k / Cz: the slope is negative, so the top shows higher fractions.
    EXPECT_NEAR(predicted, -0.8 * c.height_m() * lens.line_tilt() *
                               display::fraction_per_tan(c.view_cone_deg) / 0.5, 1e-3);
    EXPECT_GT(predicted, 0.05);
    EXPECT_NEAR(measured, predicted, 0.006);
    // Each end on its own, too: the camera's height shifts both alike.
    EXPECT_NEAR(wrapped(seen_at(top) - predicted_at(top)), 0.0, 0.006);
    EXPECT_NEAR(wrapped(seen_at(bottom) - predicted_at(bottom)), 0.0, 0.006);
  }
}

}  // namespace
}  // namespace lfd::sim
