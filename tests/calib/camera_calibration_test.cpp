// lfd camera calibrate: the intrinsics of a known camera come back from synthesized photos of
// the printed board, and what cannot be calibrated is refused or flagged.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "calib/camera/board_photographer.hpp"
#include "calib/camera/camera_calibration.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

class CameraCalibrationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("lfd_camera_calibration_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path write(const std::string& name, const cv::Mat& image) {
    const auto path = dir_ / name;
    cv::imwrite(path.string(), image);
    return path;
  }
  std::filesystem::path dir_;
};

TEST(CameraCalibration, RecoversKnownIntrinsicsFromEightTiltedPoses) {
  const CameraBoardSpec board;
  const KnownCamera camera;
  const CameraCalibration c = calibrate_camera(detect_board_photos(board, camera, tilted_poses()),
                                               {}, camera.size, CameraCalibrationOptions{});
  const auto& K = c.intrinsics.camera_matrix;
  EXPECT_EQ(c.usable, 8);
  EXPECT_NEAR(K(0, 0) / camera.K(0, 0), 1.0, 0.005);
  EXPECT_NEAR(K(1, 1) / camera.K(1, 1), 1.0, 0.005);
  EXPECT_NEAR(K(0, 2), camera.K(0, 2), 3.0);
  EXPECT_NEAR(K(1, 2), camera.K(1, 2), 3.0);
  EXPECT_NEAR(c.intrinsics.distortion.at(0), camera.distortion[0], 0.03);
  EXPECT_LT(c.rms_px, 0.3);
  EXPECT_LT(c.focal_sigma_rel, 0.005);
  EXPECT_EQ(c.intrinsics.width, 640);
  EXPECT_EQ(c.intrinsics.height, 480);
  EXPECT_TRUE(c.pose_advice.empty()) << c.pose_advice;
  for (const auto& p : c.photos) {
    EXPECT_GT(p.tilt_deg, 20.0) << p.name;
    EXPECT_NEAR(p.distance_mm, 440, 30) << p.name;
  }
  EXPECT_GT(c.tilt_range_x_deg, 40);
  EXPECT_GT(c.tilt_range_y_deg, 40);
}

TEST(CameraCalibration, TooFewUsablePhotosAreRefused) {
  const CameraBoardSpec board;
  const KnownCamera camera;
  auto poses = tilted_poses();
  poses.resize(3);
  EXPECT_THROW(calibrate_camera(detect_board_photos(board, camera, poses), {}, camera.size,
                                CameraCalibrationOptions{}),
               InputError);
}

TEST(CameraCalibration, HeadOnPosesAreFlaggedAsNotVariedEnough) {
  const CameraBoardSpec board;
  const KnownCamera camera;
  std::vector<BoardPose> head_on;
  for (int i = 0; i < 6; ++i)
    head_on.push_back({double(i % 3) - 1, double(i % 2) * 2 - 1, 4.0 * i,
                       {0.01 * (i % 3 - 1), 0.01 * (i % 2), 0.40 + 0.01 * i}});
  const CameraCalibration c =
      calibrate_camera(detect_board_photos(board, camera, head_on), {}, camera.size, {});
  EXPECT_FALSE(c.pose_advice.empty());
  EXPECT_LT(c.tilt_range_x_deg, 10);
}

TEST_F(CameraCalibrationTest, PhotoWithoutTheBoardIsRefusedByName) {
  const CameraBoardSpec board;
  const KnownCamera camera;
  const auto poses = tilted_poses();
  const BoardPhotographer photographer(board, camera);
  std::vector<std::filesystem::path> photos;
  for (size_t i = 0; i < poses.size(); ++i)
    photos.push_back(write("pose" + std::to_string(i) + ".png",
                           photographer.photograph(poses[i], i)));
  photos.push_back(write("wall.png", cv::Mat(camera.size, CV_8U, cv::Scalar(128))));
  try {
    calibrate_camera_from_photos(photos, {});
    FAIL() << "a photo without the board was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wall.png"), std::string::npos) << e.what();
  }
}

TEST_F(CameraCalibrationTest, MixedImageSizesAreRefusedByName) {
  const CameraBoardSpec board;
  const KnownCamera camera;
  const BoardPhotographer photographer(board, camera);
  const auto poses = tilted_poses();
  std::vector<std::filesystem::path> photos;
  photos.push_back(write("a.png", photographer.photograph(poses[0], 1)));
  // The same camera turned to portrait.
  cv::Mat portrait;
  cv::transpose(photographer.photograph(poses[1], 2), portrait);
  photos.push_back(write("portrait.png", portrait));
  try {
    calibrate_camera_from_photos(photos, {});
    FAIL() << "mixed sizes were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("portrait.png"), std::string::npos) << e.what();
  }
}

TEST_F(CameraCalibrationTest, CameraFileFromPhotosReadsBack) {
  const CameraBoardSpec board;
  const KnownCamera camera;
  const auto poses = tilted_poses();
  const BoardPhotographer photographer(board, camera);
  std::vector<std::filesystem::path> photos;
  for (size_t i = 0; i < poses.size(); ++i)
    photos.push_back(write("p" + std::to_string(i) + ".png",
                           photographer.photograph(poses[i], 40 + i)));
  const CameraCalibration c = calibrate_camera_from_photos(photos, {});
  const auto yaml = dir_ / "camera.yaml";
  c.intrinsics.write_yaml(yaml);
  const sim::CameraIntrinsics back = sim::CameraIntrinsics::read_yaml(yaml);
  EXPECT_NEAR(back.camera_matrix(0, 0), camera.K(0, 0), 0.005 * camera.K(0, 0));
  EXPECT_EQ(back.distortion.size(), 5u);
  EXPECT_EQ(back.width, camera.size.width);
}

TEST(CameraBoard, BadSpecIsRefused) {
  CameraBoardSpec board;
  board.squares_x = 2;
  EXPECT_THROW(board.check(), InputError);
  board = {};
  board.squares_x = board.squares_y = 30;  // 450 markers
  EXPECT_THROW(board.check(), InputError);
  board = {};
  board.marker_ratio = 0.95;
  EXPECT_THROW(board.check(), InputError);
}

}  // namespace
}  // namespace lfd::calib
