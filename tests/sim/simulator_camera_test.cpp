// The physical camera: pose conventions, OpenCV distortion, YAML intrinsics.
#include <unistd.h>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "sim/camera_model.hpp"
#include "util/error.hpp"

namespace lfd::sim {
namespace {

PhysicalCamera distorted_camera() {
  CameraIntrinsics k = CameraIntrinsics::from_fov(50.0, 1600, 1000);
  k.camera_matrix(0, 2) += 13.0;  // principal point off centre, as real cameras have
  k.camera_matrix(1, 2) -= 7.0;
  k.distortion = {-0.21, 0.06, 0.0012, -0.0008, -0.01};
  return PhysicalCamera(k, CameraPose{{0.08, -0.05, 0.55}, {0.01, 0.02, 0}, {0, 1, 0}});
}

TEST(Camera, PanelCentreProjectsToPrincipalPointWhenLookedAt) {
  const PhysicalCamera cam(CameraIntrinsics::from_fov(60.0, 1920, 1080), CameraPose{});
  Eigen::Vector2d px;
  ASSERT_TRUE(cam.project({0, 0, 0}, px));
  EXPECT_NEAR(px.x(), 959.5, 1e-9);
  EXPECT_NEAR(px.y(), 539.5, 1e-9);
}

TEST(Camera, DisplayRightAndUpAppearImageRightAndUp) {
  const PhysicalCamera cam(CameraIntrinsics::from_fov(60.0, 1920, 1080), CameraPose{});
  Eigen::Vector2d right, up;
  ASSERT_TRUE(cam.project({0.1, 0, 0}, right));
  ASSERT_TRUE(cam.project({0, 0.1, 0}, up));
  EXPECT_GT(right.x(), 959.5 + 100);  // image x right
  EXPECT_LT(up.y(), 539.5 - 100);     // image y down, display y up
}

TEST(Camera, PointsBehindTheCameraDoNotProject) {
  const PhysicalCamera cam(CameraIntrinsics::from_fov(60.0, 640, 480), CameraPose{});
  Eigen::Vector2d px;
  EXPECT_FALSE(cam.project({0, 0, 1.0}, px));
}

TEST(Camera, DistortionRoundTripThroughProjectAndPanelPoint) {
  const PhysicalCamera cam = distorted_camera();
  double worst_m = 0;
  int checked = 0;
  for (double x = -0.15; x <= 0.15; x += 0.03)
    for (double y = -0.09; y <= 0.09; y += 0.03) {
      Eigen::Vector2d px;
      ASSERT_TRUE(cam.project({x, y, 0}, px));
      if (px.x() < 0 || px.y() < 0 || px.x() > 1599 || px.y() > 999) continue;
      Eigen::Vector3d back;
      ASSERT_TRUE(cam.panel_point(px, back));
      worst_m = std::max(worst_m, (back - Eigen::Vector3d(x, y, 0)).norm());
      ++checked;
    }
  EXPECT_GT(checked, 40);
  EXPECT_LT(worst_m, 1e-7);
}

TEST(Camera, DistortionMovesImagePoints) {
  const PhysicalCamera cam = distorted_camera();
  CameraIntrinsics plain = cam.intrinsics();
  plain.distortion.clear();
  const PhysicalCamera pinhole(plain, cam.pose());
  Eigen::Vector2d a, b;
  ASSERT_TRUE(cam.project({0.15, 0.08, 0}, a));
  ASSERT_TRUE(pinhole.project({0.15, 0.08, 0}, b));
  EXPECT_GT((a - b).norm(), 5.0);  // barrel distortion pulls corners in by pixels
}

TEST(Camera, YamlRoundTrip) {
  const auto path = std::filesystem::temp_directory_path() / ("lfd_camera_roundtrip_" + std::to_string(::getpid()) + ".yaml");
  const CameraIntrinsics k = distorted_camera().intrinsics();
  k.write_yaml(path);
  const CameraIntrinsics r = CameraIntrinsics::read_yaml(path);
  EXPECT_EQ(r.width, 1600);
  EXPECT_EQ(r.height, 1000);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_DOUBLE_EQ(r.camera_matrix(i, j), k.camera_matrix(i, j));
  ASSERT_EQ(r.distortion.size(), 5u);
  EXPECT_DOUBLE_EQ(r.distortion[0], -0.21);
  std::filesystem::remove(path);
}

TEST(Camera, YamlMissingNodeNamesFileAndNode) {
  const auto path = std::filesystem::temp_directory_path() / ("lfd_camera_missing_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream f(path);
    f << "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\ncamera_matrix: !!opencv-matrix\n"
         "   rows: 3\n   cols: 3\n   dt: d\n   data: [ 500., 0., 320., 0., 500., 240., 0., 0., 1. ]\n";
  }
  try {
    CameraIntrinsics::read_yaml(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("distortion_coefficients"), std::string::npos);
  }
  std::filesystem::remove(path);
}

TEST(Camera, YamlMalformedMatrixIsInputError) {
  const auto path = std::filesystem::temp_directory_path() / ("lfd_camera_bad_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream f(path);
    f << "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\ncamera_matrix: 12\n"
         "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n"
         "   data: [ 0., 0., 0., 0., 0. ]\n";
  }
  EXPECT_THROW(CameraIntrinsics::read_yaml(path), InputError);
  std::filesystem::remove(path);
}

TEST(Camera, YamlNotYamlIsInputError) {
  const auto path = std::filesystem::temp_directory_path() / ("lfd_camera_garbage_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream f(path);
    f << "{{{{ not yaml ]]]\n";
  }
  EXPECT_THROW(CameraIntrinsics::read_yaml(path), InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace lfd::sim
