// Registration through the cover layer (docs/calibration.md, "The cover layer"): the ChArUco board
// is shown on the panel and photographed through the same acrylic block as the patterns. Board
// corners are projected here exactly (where each corner's light leaves the block toward the
// camera), so the test checks the registration's model of the block, not the detector.
#include <algorithm>

#include <gtest/gtest.h>

#include "display/cover_rays.hpp"
#include "display/visual_json.hpp"
#include "sim/patterns.hpp"
#include "calib/registration/registration.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

constexpr display::CoverLayer kBlock{0.02, 1.49};

// The corners as a camera at `pose` sees them through `cover`.
BoardDetection board_through_cover(const sim::PatternSet& set, const sim::PhysicalCamera& camera,
                                   const display::CoverLayer& cover) {
  BoardDetection board;
  board.image_size = {camera.intrinsics().width, camera.intrinsics().height};
  const Eigen::Vector3d c = camera.position();
  for (size_t id = 0; id < set.board.corners_px.size(); ++id) {
    const Eigen::Vector3d p =
        uv_to_display_m(set.nominal.display, panel_px_to_uv(set.nominal.display, set.board.corners_px[id]));
    const display::Point3 e = display::cover_exit_point({p.x(), p.y(), 0.0}, {c.x(), c.y(), c.z()}, cover);
    Eigen::Vector2d px;
    if (!camera.project(Eigen::Vector3d(e.x, e.y, e.z), px)) continue;
    board.ids.push_back(int(id));
    board.image_px.emplace_back(float(px.x()), float(px.y()));
  }
  return board;
}

sim::PatternSet patterns_for(const display::CoverLayer& cover) {
  display::Calibration nominal;
  nominal.display = display::read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json"));
  nominal.display.cover = cover;
  return sim::plan_patterns(nominal);
}

TEST(RegistrationThroughCover, FindsTheCameraWhereItIsAndThePanelPointsItSees) {
  sim::CameraPose pose;
  pose.position_m = {0.23, 0.04, 0.5};  // 25 degrees to the side of a 16" Gen2
  pose.look_at_m = {0.0, 0.0, 0.0};
  const sim::PhysicalCamera camera(sim::CameraIntrinsics::from_fov(50.0, 1280, 960), pose);
  const sim::PatternSet with_cover = patterns_for(kBlock);
  const BoardDetection board = board_through_cover(with_cover, camera, kBlock);
  ASSERT_GT(board.ids.size(), 20u);

  const Registration modelled(board, with_cover, camera.intrinsics());
  const Eigen::Vector3d error = modelled.camera_position_m() - pose.position_m;
  std::printf("through the cover: camera error (%.3f, %.3f, %.3f) mm\n", 1e3 * error.x(),
              1e3 * error.y(), 1e3 * error.z());
  EXPECT_LT(error.norm(), 1e-4);
  // Each corner's pixel maps back to the panel point under it.
  const auto uv = modelled.image_to_panel_uv(board.image_px);
  for (size_t i = 0; i < uv.size(); ++i) {
    const display::ScreenUV truth = panel_px_to_uv(with_cover.nominal.display,
                                          with_cover.board.corners_px[size_t(board.ids[i])]);
    EXPECT_NEAR(uv[i].u, truth.u, 2e-5);
    EXPECT_NEAR(uv[i].v, truth.v, 2e-5);
  }

  // Ignoring the block puts the camera about t (1 - 1/n) = 6.6 mm too near: the pose of the
  // apparent panel.
  const Registration ignored(board, patterns_for(display::CoverLayer{}), camera.intrinsics());
  const Eigen::Vector3d off = ignored.camera_position_m() - pose.position_m;
  std::printf("ignoring the cover: camera error (%.3f, %.3f, %.3f) mm\n", 1e3 * off.x(),
              1e3 * off.y(), 1e3 * off.z());
  EXPECT_GT(off.norm(), 0.8 * kBlock.apparent_shift_m());

  // What the pose cannot absorb: the view fraction the ignored registration predicts over the
  // screen (no cover, its pose) against the truth (the cover, the true pose), after removing
  // the mean (the lens center absorbs a constant). The modelled registration leaves nothing.
  const display::DisplayCalibration& d = with_cover.nominal.display;
  const double lines = display::LensModel(d).line_tilt(), cone = d.view_cone_deg;
  auto spread = [&](const Eigen::Vector3d& cam, const display::CoverLayer& cover) {
    double lo = 1e9, hi = -1e9;
    for (int j = 0; j <= 10; ++j)
      for (int i = 0; i <= 10; ++i) {
        const double px = (i / 10.0 - 0.5) * d.width_m(), py = (j / 10.0 - 0.5) * d.height_m();
        const Eigen::Vector3d t = pose.position_m;
        const double truth =
            display::seen_fraction_through_cover(t.x() - px, t.y() - py, t.z(), kBlock, lines, cone);
        const double model = display::seen_fraction_through_cover(cam.x() - px, cam.y() - py, cam.z(),
                                                         cover, lines, cone);
        lo = std::min(lo, model - truth);
        hi = std::max(hi, model - truth);
      }
    return hi - lo;
  };
  const double left_modelled = spread(modelled.camera_position_m(), kBlock);
  const double left_ignored = spread(ignored.camera_position_m(), display::CoverLayer{});
  std::printf("seen-fraction error over the screen (max - min): modelled %.5f, ignored %.5f\n",
              left_modelled, left_ignored);
  EXPECT_LT(left_modelled, 2e-4);
  EXPECT_GT(left_ignored, 5 * left_modelled);
}

}  // namespace
}  // namespace lfd::calib
