#pragma once
// Registration (docs/calibration.md section 3.1): where the panel is in a photograph. The ChArUco
// board gives corner correspondences camera pixel <-> panel point; with the camera intrinsics they
// give the homography (undistorted camera pixel -> panel (u, v)) and the camera pose in the display
// frame (docs/validation.md "The forward model": metres, panel centre origin, y up, viewer at z >
// 0). Without intrinsics, boards seen from >= 3 positions self-calibrate them.
#include <array>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"
#include "display/lens_model.hpp"
#include "sim/patterns.hpp"

namespace lfd::calib {

struct BoardDetection {
  std::vector<int> ids;                   // ChArUco corner ids
  std::vector<cv::Point2f> image_px;      // detected corners (distorted camera pixels)
  cv::Size image_size;
  int markers = 0;               // ArUco markers of the board found
  bool touches_border = false;   // some marker lies at the image border (screen cut off?)
};

// Detects the ChArUco corners in a photograph of the board pattern (8-bit grey).
BoardDetection detect_board(const cv::Mat& gray8, const sim::PatternSet& set);

// Centres of the ArUco corner markers found in a capture, by marker id.
std::map<int, cv::Point2d> detect_corner_markers(const cv::Mat& gray8);
// Their four outer corners (marker order TL, TR, BR, BL as drawn), by marker id.
std::map<int, std::array<cv::Point2d, 4>> detect_corner_marker_corners(const cv::Mat& gray8);

// Extra correspondences for the registration (the fringe blocks).
struct ExtraPoints {
  std::vector<cv::Point2f> image_px;
  std::vector<cv::Point2d> panel_px;
  std::vector<cv::Point2d> shift_px;  // as panel_shift_px, one per point (or empty)
};

// Intrinsics from the boards of >= 3 positions (cv::calibrateCamera, k1 and k2). Throws
// InputError if fewer than 3 usable boards. `focal_sigma_rel`: the focal length's relative
// 1-sigma uncertainty, from the curvature of the reprojection error around the solution.
sim::CameraIntrinsics self_calibrate(const std::vector<BoardDetection>& boards, const sim::PatternSet& set,
                                double* rms_px = nullptr, double* focal_sigma_rel = nullptr);

// Panel pixel (OpenCV coordinates) <-> screen (u, v) <-> display-frame metres.
display::ScreenUV panel_px_to_uv(const display::DisplayCalibration& d, cv::Point2d px);
Eigen::Vector3d uv_to_display_m(const display::DisplayCalibration& d, display::ScreenUV uv);

class Registration {
 public:
  // Finds the correspondences (board corners + extra points) whose physical panel points fit
  // one homography (robustly) and fits the pose to them. `panel_shift_px` (optional, one per
  // corner) moves content positions to physical ones: the lens array shows each feature
  // displaced by up to half a lens (see calibrate.cpp), which the pose must not absorb.
  Registration(const BoardDetection& board, const sim::PatternSet& set, const sim::CameraIntrinsics& camera,
               const std::vector<cv::Point2d>& panel_shift_px = {},
               const ExtraPoints& extra = {});

  const sim::CameraIntrinsics& camera() const { return camera_; }
  Eigen::Vector3d camera_position_m() const { return position_m_; }
  double reprojection_rms_px() const { return reprojection_rms_px_; }
  int corner_count() const { return corners_; }

  // Camera pixels (distorted, as photographed) -> the panel point (u, v) the camera looks at
  // there: the pixel's ray through the pose, met with the panel plane. This is the physical
  // point, not the content the lens array shows there (that is shifted by up to half a lens,
  // with a jump of a whole lens where the seen view fraction wraps, so it is no homography;
  // the solver adds the shift from its current estimate).
  std::vector<display::ScreenUV> image_to_panel_uv(const std::vector<cv::Point2f>& image_px) const;
  // Panel (u, v) -> distorted camera pixel, through the pose (for checks).
  std::vector<cv::Point2d> uv_to_image(const std::vector<display::ScreenUV>& uv) const;

 private:
  sim::CameraIntrinsics camera_;
  display::DisplayCalibration display_;
  cv::Vec3d rvec_, tvec_;
  Eigen::Vector3d position_m_;
  double reprojection_rms_px_ = 0;
  int corners_ = 0;
};

}  // namespace lfd::calib
