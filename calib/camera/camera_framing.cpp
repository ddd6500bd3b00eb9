#include "calib/camera/camera_framing.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <opencv2/calib3d.hpp>

namespace lfd::calib {

const char* to_string(FramingVerdict verdict) {
  switch (verdict) {
    case FramingVerdict::kNoBoard: return "no board";
    case FramingVerdict::kCutOff: return "cut off";
    case FramingVerdict::kTooSmall: return "too small";
    case FramingVerdict::kGood: return "good";
  }
  return "?";
}

Framing assess_framing(const CharucoCorners& found, const sim::PatternSet& set, cv::Size image_size,
                       const FramingLimits& limits) {
  Framing f;
  f.markers = found.markers;
  f.corners = int(found.ids.size());
  if (f.corners < std::max(limits.min_corners, 4)) {
    f.message = fmt::format("no board in view ({} markers, {} corners): aim at the board on the "
                            "display, in focus",
                            f.markers, f.corners);
    return f;
  }
  std::vector<cv::Point2d> panel, image;
  for (size_t i = 0; i < found.ids.size(); ++i) {
    const int id = found.ids[i];
    if (id < 0 || size_t(id) >= set.board.corners_px.size()) continue;
    panel.push_back(set.board.corners_px[size_t(id)]);
    image.push_back(cv::Point2d(found.image_px[i]));
  }
  const cv::Mat h = panel.size() >= 4 ? cv::findHomography(panel, image, 0) : cv::Mat();
  if (h.empty()) {
    f.message = "the board's corners found do not fit a plane: hold the camera still";
    return f;
  }
  // The panel's outer edges (pixel centres at integers, so the edges sit half a pixel out).
  const double w = set.nominal.display.screen_w, hgt = set.nominal.display.screen_h;
  const std::vector<cv::Point2d> panel_corners = {
      {-0.5, -0.5}, {w - 0.5, -0.5}, {w - 0.5, hgt - 0.5}, {-0.5, hgt - 0.5}};
  std::vector<cv::Point2d> outline;
  cv::perspectiveTransform(panel_corners, outline, h);
  std::copy(outline.begin(), outline.end(), f.panel_outline_px.begin());

  const auto [min_x, max_x] = std::minmax({outline[0].x, outline[1].x, outline[2].x, outline[3].x});
  const auto [min_y, max_y] = std::minmax({outline[0].y, outline[1].y, outline[2].y, outline[3].y});
  f.fill = std::max((max_x - min_x) / image_size.width, (max_y - min_y) / image_size.height);
  const cv::Point2d top = outline[1] - outline[0];
  f.roll_deg = std::atan2(top.y, top.x) * 180.0 / M_PI;
  f.side_ratio = cv::norm(outline[3] - outline[0]) / std::max(1e-9, cv::norm(outline[2] - outline[1]));

  const double mx = limits.margin_frac * image_size.width, my = limits.margin_frac * image_size.height;
  std::vector<std::string> cut;
  if (min_x < mx) cut.push_back("left");
  if (max_x > image_size.width - 1 - mx) cut.push_back("right");
  if (min_y < my) cut.push_back("top");
  if (max_y > image_size.height - 1 - my) cut.push_back("bottom");
  f.cut_sides = fmt::format("{}", fmt::join(cut, ", "));

  const std::string geometry =
      fmt::format("panel fills {:.0f} % of the frame, roll {:+.1f} deg, left/right edge {:.2f}",
                  100 * f.fill, f.roll_deg, f.side_ratio);
  if (!cut.empty()) {
    f.verdict = FramingVerdict::kCutOff;
    f.message = fmt::format("panel cut off at the {} ({}): move back or re-aim", f.cut_sides, geometry);
  } else if (f.fill < limits.min_fill) {
    f.verdict = FramingVerdict::kTooSmall;
    f.message = fmt::format("panel too small ({}): move closer, aim for 50-70 %", geometry);
  } else {
    f.verdict = FramingVerdict::kGood;
    f.message = fmt::format("good: {}", geometry);
  }
  return f;
}

}  // namespace lfd::calib
