// End to end through the interlacer and a full capture: a quilt whose tile j is the grey level j /
// (V - 1), interlaced for the display and photographed, shows at every camera pixel the view the
// optics send toward the camera there (docs/validation.md "The forward model": f_seen varies across
// the screen for a camera at a finite distance).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "sim/simulator.hpp"
#include "interlace/interlacer.hpp"
#include "render/quilt_layout.hpp"
#include "tests/sim/simulator_test_support.hpp"

namespace lfd::validate {
namespace {

TEST(InterlacedCapture, EveryCameraPixelSeesTheViewItsDirectionSelects) {
  const int views = 16;
  const display::LensModel lens(sim::testing::small_display());
  const auto& c = lens.calibration();
  render::QuiltLayout layout;
  layout.cols = 4;
  layout.rows = 4;
  layout.views = views;
  layout.aspect = double(c.screen_w) / c.screen_h;
  layout.width = 4 * 32;
  layout.height = 4 * 18;
  ImageF quilt(layout.width, layout.height, 3);
  for (int v = 0; v < views; ++v)
    for (int y = 0; y < layout.tile_height(); ++y)
      for (int x = 0; x < layout.tile_width(); ++x)
        for (int ch = 0; ch < 3; ++ch)
          quilt.at(layout.tile_x(v) + x, layout.tile_y_top_down(v) + y, ch) = float(v) / (views - 1);
  const ImageF panel = interlace::interlace(quilt, layout, lens);
  const ImageF white(c.screen_w, c.screen_h, 3, 1.0f);

  const sim::DisplaySimulator sim{lens};
  const sim::PhysicalCamera camera(sim::CameraIntrinsics::from_fov(45.0, 192, 108),
                                     sim::CameraPose{{0.04, 0.01, 0.5}, {0, 0, 0}, {0, 1, 0}});
  sim::CaptureEffects fx;
  fx.supersample = 2;
  fx.exposure = 0.3;  // nothing clips: the ratio below is linear
  const ImageF seen = sim.capture(panel, camera, fx);
  const ImageF reference = sim.capture(white, camera, fx);

  const double two_tan = 2.0 * std::tan(0.5 * c.view_cone_deg * std::numbers::pi / 180.0);
  int agree = 0, total = 0;
  for (int y = 0; y < 108; ++y)
    for (int x = 0; x < 192; ++x) {
      Eigen::Vector3d p;
      ASSERT_TRUE(camera.panel_point({double(x), double(y)}, p));
      if (std::abs(p.x()) > 0.45 * c.width_m() || std::abs(p.y()) > 0.45 * c.height_m()) continue;
      double f = 0.5 + (camera.position().x() - p.x()) / camera.position().z() / two_tan;
      f -= std::floor(f);
      if (f < 0.05 || f > 0.95) continue;  // at the cone edge the view wraps within a pixel
      const double expected = std::floor(f * views);
      for (int ch = 0; ch < 3; ++ch) {
        if (reference.at(x, y, ch) < 0.15f) continue;  // too little of this channel to read
        const double view = seen.at(x, y, ch) / reference.at(x, y, ch) * (views - 1);
        agree += std::abs(view - expected) <= 1.5;
        ++total;
      }
    }
  ASSERT_GT(total, 5000);
  EXPECT_GT(double(agree) / total, 0.97) << agree << " of " << total;
}

}  // namespace
}  // namespace lfd::validate
