#include "pipeline/camera_pose_count.hpp"

#include <algorithm>

#include "calib/camera/board_photographer.hpp"
#include "calib/camera/camera_calibration.hpp"

namespace lfd::pipeline {

namespace {

// The 8 tilted poses of the photographing guide and 4 milder, off-centre ones, as a user adds
// them.
std::vector<calib::BoardPose> twelve_tilted_poses() {
  std::vector<calib::BoardPose> poses = calib::tilted_poses();
  poses.push_back({15, -10, 20, {0.03, 0.02, 0.38}});
  poses.push_back({-12, 18, -15, {-0.03, -0.02, 0.40}});
  poses.push_back({20, 12, 30, {0.02, -0.03, 0.50}});
  poses.push_back({-18, -15, -25, {-0.02, 0.03, 0.36}});
  return poses;
}

// Eight poses nearly head-on (tilts under 5 deg).
std::vector<calib::BoardPose> head_on_poses() {
  std::vector<calib::BoardPose> poses;
  for (int i = 0; i < 8; ++i)
    poses.push_back({double(i % 3) * 2 - 2, double(i % 2) * 4 - 2, 4.0 * i,
                     {0.01 * (i % 3 - 1), 0.01 * (i % 2), 0.38 + 0.015 * i}});
  return poses;
}

PoseCountRow row_of(const calib::CameraCalibration& c, const calib::KnownCamera& camera,
                    std::string poses, int count, bool fix_k3) {
  const auto& K = c.intrinsics.camera_matrix;
  PoseCountRow r;
  r.poses = std::move(poses);
  r.count = count;
  r.fix_k3 = fix_k3;
  r.fx_error_pct = 100 * (K(0, 0) / camera.K(0, 0) - 1);
  r.fx_sigma_pct = 100 * c.focal_sigma_rel;
  r.cx_error_px = K(0, 2) - camera.K(0, 2);
  r.cy_error_px = K(1, 2) - camera.K(1, 2);
  r.rms_px = c.rms_px;
  r.pose_advice = !c.pose_advice.empty();
  return r;
}

}  // namespace

std::vector<PoseCountRow> measure_camera_pose_count(int max_tilted) {
  const calib::CameraBoardSpec board;
  const calib::KnownCamera camera;
  std::vector<calib::BoardPose> tilted = twelve_tilted_poses();
  tilted.resize(size_t(std::clamp(max_tilted, 3, int(tilted.size()))));
  const auto all = calib::detect_board_photos(board, camera, tilted);
  std::vector<PoseCountRow> rows;
  for (size_t n = 3; n <= all.size(); ++n) {
    calib::CameraCalibrationOptions options;
    options.min_photos = 3;
    const std::vector<calib::CharucoCorners> first(all.begin(), all.begin() + long(n));
    for (bool fix_k3 : {false, true}) {
      options.fix_k3 = fix_k3;
      const auto c = calib::calibrate_camera(first, {}, camera.size, options);
      rows.push_back(row_of(c, camera, std::to_string(n) + " tilted", int(n), fix_k3));
    }
  }
  const auto c = calib::calibrate_camera(calib::detect_board_photos(board, camera, head_on_poses()),
                                         {}, camera.size, calib::CameraCalibrationOptions{});
  rows.push_back(row_of(c, camera, "8 head-on", 8, false));
  return rows;
}

}  // namespace lfd::pipeline
