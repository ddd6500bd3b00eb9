#include "calib/camera/charuco_detection.hpp"

#include <algorithm>

#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

namespace lfd::calib {

CharucoCorners detect_charuco_corners(const cv::Mat& gray8,
                                      const cv::Ptr<cv::aruco::CharucoBoard>& board,
                                      int min_markers) {
  CharucoCorners out;
  auto params = cv::aruco::DetectorParameters::create();
  params->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
  std::vector<std::vector<cv::Point2f>> marker_corners, rejected;
  std::vector<int> marker_ids;
  cv::aruco::detectMarkers(gray8, board->dictionary, marker_corners, marker_ids, params,
                           rejected);
  out.markers = int(marker_ids.size());
  if (out.markers < std::max(min_markers, 1)) return out;
  cv::aruco::interpolateCornersCharuco(marker_corners, marker_ids, gray8, board, out.image_px,
                                       out.ids, cv::noArray(), cv::noArray(), 2);
  // The interpolated corners of OpenCV 4.6 sit about half a pixel off (measured on rendered
  // boards); a saddle-point refinement of our own removes that bias.
  if (!out.image_px.empty()) {
    const auto& e = out.image_px;
    double spacing = 1e9;  // window: a third of the nearest corner spacing, 2..8 px
    for (size_t i = 0; i < e.size(); ++i)
      for (size_t j = i + 1; j < e.size(); ++j)
        spacing = std::min(spacing, double(cv::norm(e[i] - e[j])));
    const int win = std::clamp(int(spacing / 3), 2, 8);
    cv::cornerSubPix(gray8, out.image_px, cv::Size(win, win), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-3));
  }
  return out;
}

}  // namespace lfd::calib
