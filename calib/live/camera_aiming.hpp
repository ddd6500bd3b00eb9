#pragma once
// Aiming the camera at a position before its photographs: the camera's live image with the
// board detection (calib/charuco_detection.hpp) and the framing (calib/camera_framing.hpp)
// drawn on it, in the preview window, until the user confirms with Enter.
#include <functional>
#include <string>

#include <opencv2/core.hpp>

#include "calib/camera_framing.hpp"
#include "calib/live_devices.hpp"
#include "calib/patterns.hpp"

namespace lfd::calib {

class PreviewWindow;

// `frame` (CV_32FC3 RGB in [0, 1]) as 8-bit RGB with the corners found (dots), the panel's
// outline (green: good, yellow: too small, red: cut off) and the framing message on top.
cv::Mat draw_framing(const cv::Mat& frame, const CharucoCorners& found, const Framing& framing);

// One preview frame: detects the board in `frame`, judges the framing and draws both.
struct PreviewFrame {
  Framing framing;
  cv::Mat drawn;  // 8-bit RGB
};
PreviewFrame preview_frame(const cv::Mat& frame, const PatternSet& set);

// Shows preview frames from `camera` in `window` (null: none; the verdict goes to the
// terminal) until Enter arrives in the terminal, the preview window or where `poll_other`
// says (the pattern window). Prints the framing line whenever its verdict changes. Returns
// the last framing.
Framing aim_camera(FrameSource& camera, const PatternSet& set, PreviewWindow* window,
                   const std::string& prompt, const std::function<bool()>& poll_other);

}  // namespace lfd::calib
