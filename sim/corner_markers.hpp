#pragma once
// Where the corner markers of a pattern (sim/patterns.hpp, CornerMarkers) lie on the panel: the
// drawing and the registration, which uses their outer corners as correspondences at the
// screen's corners (calib/calibration_stages.cpp, register_position), share this one placement.
#include <array>
#include <cmath>

#include <opencv2/core.hpp>

#include "sim/patterns.hpp"

namespace lfd::sim {

// The top-left panel pixel of corner marker `corner`'s square (its black border included).
inline cv::Point marker_origin_px(const CornerMarkers& m, int corner) {
  const cv::Point2d c = m.centres_px.at(size_t(corner));
  return {int(std::lround(c.x + 0.5 - m.side_px / 2.0)),
          int(std::lround(c.y + 0.5 - m.side_px / 2.0))};
}

// The square's outer corners in OpenCV panel coordinates (pixel centres at integers), in the
// order ArUco reports a marker's corners: TL, TR, BR, BL as drawn.
inline std::array<cv::Point2d, 4> marker_outer_corners_px(const CornerMarkers& m, int corner) {
  const cv::Point o = marker_origin_px(m, corner);
  const double x0 = o.x - 0.5, y0 = o.y - 0.5, s = m.side_px;
  return {cv::Point2d(x0, y0), cv::Point2d(x0 + s, y0), cv::Point2d(x0 + s, y0 + s),
          cv::Point2d(x0, y0 + s)};
}

}  // namespace lfd::sim
