// Framing before a position's photographs (calib/camera/camera_framing.hpp): the panel's outline
// from the board corners found, and the verdict. The "detections" are the board's own corners
// mapped into a 640x480 frame by a known similarity or perspective map, so the true outline
// is known exactly.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "calib/camera/camera_framing.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

const cv::Size kFrame(640, 480);

sim::PatternSet portrait_set() {
  display::Calibration nominal;
  nominal.display =
      display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  return sim::plan_patterns(nominal);
}

// Panel pixel -> image pixel: the panel's height is `fill` of the frame's height, its centre
// at `centre`, turned `roll_deg` clockwise; `keystone` > 0 makes the left edge longer.
cv::Matx33d panel_to_image(const sim::PatternSet& set, double fill, cv::Point2d centre,
                           double roll_deg, double keystone) {
  const double w = set.nominal.display.screen_w, h = set.nominal.display.screen_h;
  const double s = fill * kFrame.height / h, a = roll_deg * M_PI / 180;
  const cv::Matx33d to_centre(1, 0, -(w - 1) / 2, 0, 1, -(h - 1) / 2, 0, 0, 1);
  const cv::Matx33d persp(1, 0, 0, 0, 1, 0, keystone / w, 0, 1);
  const cv::Matx33d place(s * std::cos(a), -s * std::sin(a), centre.x, s * std::sin(a),
                          s * std::cos(a), centre.y, 0, 0, 1);
  return place * persp * to_centre;
}

CharucoCorners seen(const sim::PatternSet& set, const cv::Matx33d& map, size_t max_corners = 1000) {
  CharucoCorners c;
  c.markers = 12;
  for (size_t id = 0; id < set.board.corners_px.size() && id < max_corners; ++id) {
    const cv::Point2d p = set.board.corners_px[id];
    const cv::Vec3d q = map * cv::Vec3d(p.x, p.y, 1);
    c.image_px.emplace_back(float(q[0] / q[2]), float(q[1] / q[2]));
    c.ids.push_back(int(id));
  }
  return c;
}

struct Case {
  std::string name;
  double fill;
  cv::Point2d centre;
  double roll_deg;
  FramingVerdict verdict;
  std::string cut_sides;
};

TEST(CameraFraming, VerdictFromThePanelOutline) {
  const sim::PatternSet set = portrait_set();
  const std::vector<Case> cases = {
      {"centred, 60 %", 0.6, {320, 240}, 0, FramingVerdict::kGood, ""},
      {"centred, 90 %", 0.9, {320, 240}, 0, FramingVerdict::kGood, ""},
      {"far, 25 %", 0.25, {320, 240}, 0, FramingVerdict::kTooSmall, ""},
      {"too close, 110 %", 1.1, {320, 240}, 0, FramingVerdict::kCutOff, "top, bottom"},
      {"off to the left", 0.6, {60, 240}, 0, FramingVerdict::kCutOff, "left"},
      {"off to the bottom right", 0.6, {600, 400}, 0, FramingVerdict::kCutOff, "right, bottom"},
      {"turned 8 deg", 0.6, {320, 240}, 8, FramingVerdict::kGood, ""},
  };
  for (const Case& c : cases) {
    const Framing f = assess_framing(seen(set, panel_to_image(set, c.fill, c.centre, c.roll_deg, 0)),
                                     set, kFrame);
    EXPECT_EQ(f.verdict, c.verdict) << c.name << ": " << f.message;
    EXPECT_EQ(f.cut_sides, c.cut_sides) << c.name;
    EXPECT_NEAR(f.roll_deg, c.roll_deg, 0.01) << c.name;
    if (c.roll_deg == 0) EXPECT_NEAR(f.fill, c.fill, 0.005) << c.name;
  }
}

TEST(CameraFraming, OutlineIsThePanelsCornersInTheImage) {
  const sim::PatternSet set = portrait_set();
  const cv::Matx33d map = panel_to_image(set, 0.6, {320, 240}, 3, 0.2);
  const Framing f = assess_framing(seen(set, map), set, kFrame);
  const double w = set.nominal.display.screen_w, h = set.nominal.display.screen_h;
  const cv::Point2d corners[4] = {{-0.5, -0.5}, {w - 0.5, -0.5}, {w - 0.5, h - 0.5}, {-0.5, h - 0.5}};
  for (int i = 0; i < 4; ++i) {
    const cv::Vec3d q = map * cv::Vec3d(corners[i].x, corners[i].y, 1);
    EXPECT_NEAR(f.panel_outline_px[size_t(i)].x, q[0] / q[2], 0.05) << i;
    EXPECT_NEAR(f.panel_outline_px[size_t(i)].y, q[1] / q[2], 0.05) << i;
  }
  EXPECT_GT(f.side_ratio, 1.05);  // the left edge nearer, so longer
}

TEST(CameraFraming, TooFewCornersIsNoBoard) {
  const sim::PatternSet set = portrait_set();
  const Framing f =
      assess_framing(seen(set, panel_to_image(set, 0.6, {320, 240}, 0, 0), 5), set, kFrame);
  EXPECT_EQ(f.verdict, FramingVerdict::kNoBoard);
  EXPECT_NE(f.message.find("no board"), std::string::npos) << f.message;
}

}  // namespace
}  // namespace lfd::calib
