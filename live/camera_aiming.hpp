#pragma once
// Aiming the camera at a position before its photographs: the camera's live image with the
// board detection (calib/camera/charuco_detection.hpp) and the framing (calib/camera/camera_framing.hpp)
// drawn on it, in the preview window, until the user confirms with Enter.
#include <functional>
#include <string>

#include <opencv2/core.hpp>

#include "calib/camera/camera_framing.hpp"
#include "live/live_devices.hpp"
#include "sim/patterns.hpp"

namespace lfd::live {

class PreviewWindow;

// `frame` (CV_32FC3 RGB in [0, 1]) as 8-bit RGB with the corners found (dots), the panel's
// outline (green: good, yellow: too small, red: cut off) and the framing message on top.
cv::Mat draw_framing(const cv::Mat& frame, const calib::CharucoCorners& found, const calib::Framing& framing);

// One preview frame: detects the board in `frame`, judges the framing and draws both.
struct PreviewFrame {
  calib::Framing framing;
  cv::Mat drawn;  // 8-bit RGB
};
PreviewFrame preview_frame(const cv::Mat& frame, const sim::PatternSet& set);

// Shows preview frames from `camera` in `window` (null: none; the verdict goes to the
// terminal) until Enter arrives in the terminal, the preview window or where `poll_other`
// says (the pattern window). Prints the framing line whenever its verdict changes. Returns
// the last framing.
calib::Framing aim_camera(FrameSource& camera, const sim::PatternSet& set, PreviewWindow* window,
                   const std::string& prompt, const std::function<bool()>& poll_other);

}  // namespace lfd::live
