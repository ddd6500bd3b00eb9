#pragma once
// How many board poses `lfd camera calibrate` needs (`lfd bench camera-poses`;
// docs/calibration.md, "How many poses"): a known camera (calib/camera/board_photographer.hpp)
// photographs the default board from the first N of 12 tilted poses (8 tilted 25-30 deg both
// ways about both axes, then 4 milder, off-centre ones) and from 8 head-on ones (tilts under
// 5 deg, as people first take them); each set is calibrated, with k3 free and fixed.
#include <string>
#include <vector>

namespace lfd::pipeline {

struct PoseCountRow {
  std::string poses;          // "3 tilted", "8 head-on"
  int count = 0;
  bool fix_k3 = false;
  double fx_error_pct = 0;    // fx / true fx - 1, in percent
  double fx_sigma_pct = 0;    // OpenCV's 1-sigma of fx / fx, in percent
  double cx_error_px = 0, cy_error_px = 0;
  double rms_px = 0;          // reprojection error
  bool pose_advice = false;   // the calibration called the poses not varied enough
};

// The first 3..max_tilted (at most 12) tilted poses, each with k3 free and fixed, then the 8
// head-on ones (k3 free).
std::vector<PoseCountRow> measure_camera_pose_count(int max_tilted = 12);

}  // namespace lfd::pipeline
