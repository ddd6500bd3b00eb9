#pragma once
// A physical camera in the display frame (docs/validation.md "The forward model": panel plane z =
// 0, x right, y up, origin at the panel centre, metres, viewer at z > 0). Intrinsics and distortion
// follow OpenCV (camera x right, y down, z forward; `camera_matrix`, `distortion_coefficients` in
// OpenCV YAML); projection goes through cv::projectPoints' model so real calibration files from
// OpenCV work unchanged.
#include <filesystem>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace lfd::sim {

struct CameraIntrinsics {
  int width = 1920;
  int height = 1080;
  cv::Matx33d camera_matrix = cv::Matx33d::eye();
  std::vector<double> distortion;  // k1 k2 p1 p2 [k3 ...], may be empty

  // A distortion-free pinhole with the given horizontal field of view.
  static CameraIntrinsics from_fov(double horizontal_fov_deg, int width, int height);
  // OpenCV FileStorage YAML (not XML or JSON) with camera_matrix, distortion_coefficients and
  // image_width / image_height. Throws InputError naming the file and the missing node.
  static CameraIntrinsics read_yaml(const std::filesystem::path& path);
  void write_yaml(const std::filesystem::path& path) const;
};

struct CameraPose {
  Eigen::Vector3d position_m{0, 0, 0.6};
  Eigen::Vector3d look_at_m{0, 0, 0};
  Eigen::Vector3d up{0, 1, 0};
};

class PhysicalCamera {
 public:
  PhysicalCamera(CameraIntrinsics intrinsics, CameraPose pose);
  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  const CameraPose& pose() const { return pose_; }
  // World-to-camera rotation (rows: camera x, y, z axes in world coordinates).
  const Eigen::Matrix3d& rotation() const { return rotation_; }
  Eigen::Vector3d position() const { return pose_.position_m; }

  // Image position (pixels, distortion applied) of a world point; false if behind the camera.
  bool project(const Eigen::Vector3d& world, Eigen::Vector2d& pixel) const;
  // The point on the panel plane z = 0 seen at image position `pixel` (distortion removed).
  bool panel_point(const Eigen::Vector2d& pixel, Eigen::Vector3d& on_panel) const;

 private:
  CameraIntrinsics intrinsics_;
  CameraPose pose_;
  Eigen::Matrix3d rotation_;
};

}  // namespace lfd::sim
