#pragma once
// Is the camera aimed well enough to photograph? Judged from the display's board as the
// camera sees it (one frame of the live preview, before a position's photographs): the
// panel's outline in the image follows from the board corners found (a homography from panel
// pixels to image pixels, since the board is the same flat image in every view), and with it
// whether the whole panel is in the frame, how much of the frame it fills and how it is
// turned. Pure: no window, no camera (live/ draws it).
#include <array>
#include <string>

#include <opencv2/core.hpp>

#include "calib/camera/charuco_detection.hpp"
#include "sim/patterns.hpp"

namespace lfd::calib {

enum class FramingVerdict { kNoBoard, kCutOff, kTooSmall, kGood };
const char* to_string(FramingVerdict verdict);

struct FramingLimits {
  int min_corners = 6;        // board corners needed for the outline (a homography needs 4)
  double min_fill = 0.4;      // the panel's extent over the frame's (the guide asks 50-70 %)
  double margin_frac = 0.01;  // an outline corner this close to the frame's edge is cut off
};

struct Framing {
  FramingVerdict verdict = FramingVerdict::kNoBoard;
  int corners = 0, markers = 0;
  // The panel's corners in the image (OpenCV pixels): top-left, top-right, bottom-right,
  // bottom-left of the panel as it shows the pattern. Unset without a board.
  std::array<cv::Point2d, 4> panel_outline_px{};
  double fill = 0;          // max(outline width / frame width, outline height / frame height)
  double roll_deg = 0;      // the panel's top edge from the frame's horizontal, clockwise
  double side_ratio = 1;    // left edge / right edge length: > 1 seen from the left
  std::string cut_sides;    // "left, top": frame edges the panel crosses
  std::string message;      // one line for the user: what is wrong and what to do, or "good"
};

// `found`: the board detection in a frame of `image_size`; `set`: the patterns (the board's
// layout on the panel and the panel's size).
Framing assess_framing(const CharucoCorners& found, const sim::PatternSet& set, cv::Size image_size,
                       const FramingLimits& limits = {});

}  // namespace lfd::calib
