#pragma once
// The camera's intrinsics from views of the (planar) panel: OpenCV's calibrateCamera with the
// focal length's uncertainty beside it. Used twice without --camera (docs/calibration.md,
// 3.1, "Without `--camera`"): first with
// the ChArUco corners of >= 3 positions, then with the thousands of fringe correspondences
// of every position (lens shift removed), which pin the focal length and the principal point
// down far better than ~40 corners a position.
#include <vector>

#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"

namespace lfd::calib {

// One photograph's correspondences: panel points (display frame, metres, z = 0) and where
// the photo shows them (distorted camera pixels).
struct PlanarView {
  std::vector<cv::Point3f> panel_m;
  std::vector<cv::Point2f> image_px;
};

struct PlanarCalibration {
  sim::CameraIntrinsics camera;
  double rms_px = 0;
  // Relative 1-sigma of the focal length, from the curvature of the summed squared
  // reprojection error with the focal length held 5 % off and everything else refitted
  // (1-sigma: chi^2 + 1 with the noise the fit measured, f sigma_f = rms sqrt(2 / S''),
// inflated for errors that neighbouring points share).
  double focal_sigma_rel = 0;
  // Its variance inflation for errors neighbouring points share (>= 1; included above).
  double error_inflation = 1;
};

// fx = fy, no tangential distortion, k1 and k2 (what planar views can determine). `guess`:
// the start (else OpenCV's initCameraMatrix2D from the views).
PlanarCalibration calibrate_planar_views(const std::vector<PlanarView>& views, cv::Size size,
                                         const sim::CameraIntrinsics* guess = nullptr);

}  // namespace lfd::calib
