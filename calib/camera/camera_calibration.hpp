#pragma once
// A camera's intrinsics from photographs of a printed ChArUco board (`lfd camera calibrate`):
// OpenCV's planar calibration (Zhang's method through calibrateCameraCharuco) with what a user
// needs to judge it: the reprojection error overall and per photo, how well the focal length
// is determined, and whether the board was tilted enough, and about both axes, to determine
// it at all (boards seen head-on leave the focal length trading off against the distance).
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"
#include "calib/camera/charuco_detection.hpp"

namespace lfd::calib {

// The printed board. Only the squares and the marker-to-square ratio matter for detection;
// the square size in millimetres scales the poses, never the intrinsics.
struct CameraBoardSpec {
  int squares_x = 9, squares_y = 6;  // A4 / Letter landscape at 30 mm squares
  double square_mm = 30;
  double marker_ratio = 0.75;         // marker side / square side
  // Throws InputError naming the field (fewer than 3 squares a side, more markers than the
  // dictionary holds, a ratio outside (0.3, 0.9)).
  void check() const;
  cv::Ptr<cv::aruco::CharucoBoard> make() const;
};

// The board as an image to print (or show full screen): `square_px` pixels per square and a
// white margin of `margin_px` on every side. 8-bit grey.
cv::Mat render_camera_board(const CameraBoardSpec& board, int square_px, int margin_px);

struct CameraCalibrationOptions {
  CameraBoardSpec board;
  int min_photos = 6;         // usable photos needed (docs/calibration.md: how many poses)
  int min_corners = 12;       // board corners a photo needs to count as usable
  bool fix_k3 = false;        // k1 k2 p1 p2 only (narrow lenses, few photos)
  double min_tilt_deg = 15;   // a pose tilted less than this adds little about the focal length
  void check() const;
};

// One photograph: what was found and how well the calibration explains it.
struct CameraPhoto {
  std::string name;            // file, for messages
  int markers = 0, corners = 0;
  bool usable = false;         // enough corners to enter the calibration
  double rms_px = 0;           // its reprojection error (usable photos)
  double tilt_deg = 0;         // angle between the board's normal and the optical axis
  double tilt_about_x_deg = 0, tilt_about_y_deg = 0;  // its parts (camera axes, signed)
  double distance_mm = 0;      // camera to board centre
};

struct CameraCalibration {
  sim::CameraIntrinsics intrinsics;
  double rms_px = 0;                       // over every corner of every usable photo
  double focal_sigma_rel = 0;              // 1-sigma of fx / fx from OpenCV's covariance
  double principal_sigma_px = 0;           // the larger 1-sigma of cx, cy
  std::vector<CameraPhoto> photos;         // in input order
  int usable = 0;
  double tilt_range_x_deg = 0, tilt_range_y_deg = 0;  // max - min of the tilts about each axis
  // Empty when the poses are varied enough; else why not (reported, not refused: the sigma
  // says what it cost).
  std::string pose_advice;
};

// Calibrates from detections made elsewhere (names for messages, one per detection). Throws
// InputError with one line for too few usable photos.
CameraCalibration calibrate_camera(const std::vector<CharucoCorners>& detections,
                                   const std::vector<std::string>& names, cv::Size image_size,
                                   const CameraCalibrationOptions& options);

// Reads and detects the photos, then calibrates. Throws InputError with one line naming the
// photo for an unreadable photo, a photo with no board in it, or a photo whose size differs
// from the first; and for too few usable photos.
CameraCalibration calibrate_camera_from_photos(const std::vector<std::filesystem::path>& photos,
                                               const CameraCalibrationOptions& options);

}  // namespace lfd::calib
