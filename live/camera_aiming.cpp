#include "live/camera_aiming.hpp"

#include <cstdio>
#include <optional>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/imgproc.hpp>

#include "sim/capture_io.hpp"
#include "live/console_prompt.hpp"
#include "live/preview_window.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {

cv::Scalar verdict_colour(calib::FramingVerdict v) {  // RGB
  switch (v) {
    case calib::FramingVerdict::kGood: return {40, 220, 40};
    case calib::FramingVerdict::kTooSmall: return {240, 210, 0};
    default: return {240, 40, 40};
  }
}

}  // namespace

cv::Mat draw_framing(const cv::Mat& frame, const calib::CharucoCorners& found, const calib::Framing& framing) {
  cv::Mat out;
  frame.convertTo(out, CV_8UC3, 255.0);
  const int thick = std::max(1, out.cols / 400);
  const cv::Scalar colour = verdict_colour(framing.verdict);
  for (const cv::Point2f& p : found.image_px)
    cv::circle(out, p, 2 * thick, {0, 160, 255}, cv::FILLED, cv::LINE_AA);
  if (framing.verdict != calib::FramingVerdict::kNoBoard) {
    std::vector<cv::Point> outline;
    for (const cv::Point2d& p : framing.panel_outline_px)
      outline.emplace_back(cvRound(p.x), cvRound(p.y));
    cv::polylines(out, outline, true, colour, 2 * thick, cv::LINE_AA);
  }
  // The message in a dark band along the top, scaled to the frame's width.
  const double font = std::max(0.4, out.cols / 1600.0);
  int baseline = 0;
  const cv::Size text = cv::getTextSize(framing.message, cv::FONT_HERSHEY_SIMPLEX, font, thick, &baseline);
  const double fit = std::min(1.0, (out.cols - 20.0) / std::max(1, text.width));
  cv::rectangle(out, {0, 0}, {out.cols, int((text.height + baseline) * fit) + 20}, {0, 0, 0},
                cv::FILLED);
  cv::putText(out, framing.message, {10, int(text.height * fit) + 10}, cv::FONT_HERSHEY_SIMPLEX,
              font * fit, colour, thick, cv::LINE_AA);
  return out;
}

PreviewFrame preview_frame(const cv::Mat& frame, const sim::PatternSet& set) {
  const calib::CharucoCorners found = calib::detect_charuco_corners(sim::to_gray8(frame), sim::make_board(set.board));
  PreviewFrame out;
  out.framing = calib::assess_framing(found, set, frame.size());
  out.drawn = draw_framing(frame, found, out.framing);
  return out;
}

calib::Framing aim_camera(FrameSource& camera, const sim::PatternSet& set, PreviewWindow* window,
                   const std::string& prompt, const std::function<bool()>& poll_other) {
  calib::Framing last;
  std::optional<calib::FramingVerdict> printed;
  wait_for_enter(prompt, [&] {
    const PreviewFrame f = preview_frame(camera.preview(), set);
    last = f.framing;
    if (printed != last.verdict) {  // the terminal hears of changes, not of every frame
      std::fprintf(stderr, "\n  camera: %s", last.message.c_str());
      printed = last.verdict;
    }
    bool enter = poll_other && poll_other();
    if (window) {
      window->show(f.drawn);
      enter |= window->poll_enter();
      if (window->closed())
        throw_input_error("the preview window was closed: live calibration cancelled");
    }
    return enter;
  });
  return last;
}

}  // namespace lfd::live
