#include "pipeline/numbered_quilt.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include <opencv2/imgproc.hpp>

namespace lfd::pipeline {

ImageF make_numbered_quilt(const render::QuiltLayout& q) {
  cv::Mat image(q.height, q.width, CV_8UC3, cv::Scalar(0, 0, 0));
  const int tw = q.tile_width(), th = q.tile_height();
  for (int k = 0; k < q.views; ++k) {
    cv::Mat tile = image(cv::Rect(q.tile_x(k), q.tile_y_top_down(k), tw, th));
    // Hue walks once around the wheel across the views (OpenCV hue range 0..180).
    cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(int(170.0 * k / std::max(1, q.views - 1)), 200, 150));
    cv::Mat rgb;
    cv::cvtColor(hsv, rgb, cv::COLOR_HSV2RGB);
    tile.setTo(rgb.at<cv::Vec3b>(0, 0));
    // A bar that moves across the tile with the view index: parallax at a glance.
    const int bar_x = int((0.1 + 0.8 * k / std::max(1, q.views - 1)) * tw);
    cv::rectangle(tile, cv::Rect(bar_x - tw / 60, 0, std::max(2, tw / 30), th),
                  cv::Scalar(255, 255, 255), cv::FILLED);
    const std::string label = std::to_string(k);
    const double scale = th / 60.0;
    const int thickness = std::max(2, th / 25);
    int baseline = 0;
    const cv::Size size =
        cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, &baseline);
    const cv::Point origin((tw - size.width) / 2, (th + size.height) / 2);
    cv::putText(tile, label, origin, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0),
                thickness * 3, cv::LINE_AA);
    cv::putText(tile, label, origin, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(255, 255, 255),
                thickness, cv::LINE_AA);
  }
  Image8 out(q.width, q.height, 3);
  std::memcpy(out.pixels.data(), image.data, out.pixels.size());
  return to_float(out);
}

}  // namespace lfd::pipeline
