#pragma once
// ChArUco corners in a photograph: the markers, the chessboard corners OpenCV interpolates
// from them, and a saddle-point refinement of those corners. One detector for the display's
// own board (registration) and for a printed board (camera calibration).
#include <vector>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>

namespace lfd::calib {

struct CharucoCorners {
  int markers = 0;                  // ArUco markers of the board found
  std::vector<cv::Point2f> image_px;  // chessboard corners (OpenCV pixel coordinates)
  std::vector<int> ids;             // their ChArUco corner ids
};

// Needs `min_markers` markers before it interpolates corners (fewer: no corners, markers set).
CharucoCorners detect_charuco_corners(const cv::Mat& gray8,
                                      const cv::Ptr<cv::aruco::CharucoBoard>& board,
                                      int min_markers = 4);

}  // namespace lfd::calib
