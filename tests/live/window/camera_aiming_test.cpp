// The live preview while aiming (live/camera_aiming.hpp, preview_window.hpp): a frame
// of the simulated camera looking at the board on the panel is judged and drawn, and the
// preview window (Xvfb) shows the drawn frame as it is.
#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "live/camera_aiming.hpp"
#include "live/preview_window.hpp"
#include "live/simulated_live_devices.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "tests/live/window/live_test_display.hpp"

namespace lfd::live {
namespace {

// A frame of the simulated camera at position 1 of 2, with the board on the panel.
struct BoardInView {
  BoardInView() {
    const sim::SyntheticUnit unit = sim::make_synthetic_unit(display::read_visual_json(test::live_test_display()));
    set = sim::plan_patterns(unit.nominal);
    screen.show(sim::render_pattern(set, *set.of_kind(sim::PatternKind::kBoard).at(0)));
    SimulatedCamera camera(unit.truth, sim::make_capture_rig(unit.truth.display, 640, 2),
                           [this] { return screen.pattern(); });
    camera.start_position(0, 2);
    frame = camera.preview();
  }
  RememberedPattern screen;
  sim::PatternSet set;
  cv::Mat frame;
};

TEST(CameraAiming, TheBoardOnTheSimulatedPanelIsFoundAndThePanelIsInView) {
  const BoardInView view;
  const PreviewFrame p = preview_frame(view.frame, view.set);
  EXPECT_GE(p.framing.corners, 12) << p.framing.message;
  EXPECT_TRUE(p.framing.verdict == calib::FramingVerdict::kGood ||
              p.framing.verdict == calib::FramingVerdict::kTooSmall)
      << p.framing.message;
  EXPECT_EQ(p.framing.cut_sides, "");
  ASSERT_EQ(p.drawn.type(), CV_8UC3);
  EXPECT_EQ(p.drawn.size(), view.frame.size());
  // The outline is drawn: the middle of the panel's top edge carries the verdict's colour
  // (green or yellow: red and blue small, green large).
  const cv::Point2d mid = 0.5 * (p.framing.panel_outline_px[0] + p.framing.panel_outline_px[1]);
  const cv::Vec3b c = p.drawn.at<cv::Vec3b>(cvRound(mid.y), cvRound(mid.x));
  EXPECT_GT(c[1], 150) << int(c[0]) << " " << int(c[1]) << " " << int(c[2]);
  EXPECT_LT(c[2], 60);
}

TEST(CameraAiming, ThePreviewWindowShowsTheDrawnFrameAsItIs) {
  const BoardInView view;
  const PreviewFrame p = preview_frame(view.frame, view.set);
  const gpu::GlfwSession glfw;
  PreviewWindow window(glfw, nullptr, p.drawn.cols, p.drawn.rows);
  window.show(p.drawn);
  const cv::Mat shown = window.read_back();
  ASSERT_EQ(shown.size(), p.drawn.size());
  cv::Mat diff;
  cv::absdiff(shown, p.drawn, diff);
  double worst = 0;
  cv::minMaxLoc(diff.reshape(1), nullptr, &worst);
  EXPECT_LE(worst, 1.0);
  EXPECT_FALSE(window.poll_enter());
}

}  // namespace
}  // namespace lfd::live
