// `lfd camera board` and `lfd camera calibrate` through the real program: the board to print,
// a camera file from tilted photos of it, and one-line refusals (exit 2).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/support/run_lfd.hpp"

namespace {

namespace fs = std::filesystem;
using lfd::test::run_lfd;

class CameraCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("lfd_camera_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // The board PNG seen by a distortion-free 640x480 camera (f = 560 px) at 0.45 m, turned by
  // `about_x` and `about_y` degrees: a homography of the printed sheet.
  void photograph(const std::string& board_png, double about_x, double about_y,
                  const std::string& out) const {
    const cv::Mat sheet = cv::imread(board_png, cv::IMREAD_GRAYSCALE);
    const double r = std::numbers::pi / 180, m_per_px = 0.030 / 40;  // --square-px 40, 30 mm
    const cv::Matx33d Rx(1, 0, 0, 0, std::cos(about_x * r), -std::sin(about_x * r), 0,
                         std::sin(about_x * r), std::cos(about_x * r));
    const cv::Matx33d Ry(std::cos(about_y * r), 0, std::sin(about_y * r), 0, 1, 0,
                         -std::sin(about_y * r), 0, std::cos(about_y * r));
    const cv::Matx33d R = Ry * Rx;
    const cv::Matx33d K(560, 0, 319.5, 0, 560, 239.5, 0, 0, 1);
    const cv::Matx33d plane(R(0, 0), R(0, 1), 0, R(1, 0), R(1, 1), 0, R(2, 0), R(2, 1), 0.45);
    const cv::Matx33d sheet_to_m(m_per_px, 0, -0.5 * sheet.cols * m_per_px, 0, m_per_px,
                                 -0.5 * sheet.rows * m_per_px, 0, 0, 1);
    cv::Mat photo;
    cv::warpPerspective(sheet, photo, cv::Mat(K * plane * sheet_to_m), cv::Size(640, 480),
                        cv::INTER_AREA, cv::BORDER_CONSTANT, cv::Scalar(100));
    cv::imwrite(out, photo);
  }
  fs::path dir_;
};

TEST_F(CameraCli, BoardIsWrittenAtTheAskedSize) {
  const auto r = run_lfd("camera board --out " + path("board.png") +
                         " --squares 9x6 --square-px 40 --margin-mm 0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const cv::Mat board = cv::imread(path("board.png"), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(board.cols, 9 * 40);
  EXPECT_EQ(board.rows, 6 * 40);
}

TEST_F(CameraCli, PrintedBoardIsSizedForItsDpi) {
  const auto r = run_lfd("camera board --out " + path("a4.png") + " --dpi 100 --margin-mm 0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const cv::Mat board = cv::imread(path("a4.png"), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(board.cols, 9 * 118);  // 30 mm at 100 DPI
  EXPECT_NE(r.output.find("270 x 180 mm"), std::string::npos) << r.output;
}

TEST_F(CameraCli, CalibratesFromTiltedPhotosAndWritesTheCameraFile) {
  ASSERT_EQ(run_lfd("camera board --out " + path("board.png") + " --square-px 40 --margin-mm 10")
                .exit_code, 0);
  fs::create_directories(dir_ / "photos");
  const double tilts[][2] = {{25, 0}, {-25, 0}, {0, 25}, {0, -25}, {20, 20}, {-20, -20}};
  for (size_t i = 0; i < std::size(tilts); ++i)
    photograph(path("board.png"), tilts[i][0], tilts[i][1],
               path("photos/" + std::to_string(i) + ".png"));
  const auto r = run_lfd("camera calibrate " + path("photos") + " --out " + path("camera.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("usable photos: 6 of 6"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("varied enough"), std::string::npos) << r.output;
  const cv::FileStorage fs(path("camera.yaml"), cv::FileStorage::READ);
  cv::Mat K;
  fs["camera_matrix"] >> K;
  ASSERT_FALSE(K.empty());
  EXPECT_NEAR(K.at<double>(0, 0), 560, 560 * 0.01);
  EXPECT_EQ(int(fs["image_width"]), 640);
  // The camera file is not replaced without --force.
  EXPECT_EQ(run_lfd("camera calibrate " + path("photos") + " --out " + path("camera.yaml"))
                .exit_code, 2);
}

TEST_F(CameraCli, TooFewPhotosAreRefusedInOneLine) {
  ASSERT_EQ(run_lfd("camera board --out " + path("board.png") + " --square-px 40 --margin-mm 10")
                .exit_code, 0);
  for (int i = 0; i < 3; ++i) photograph(path("board.png"), 20.0 * (i - 1), 10, path(std::to_string(i) + ".png"));
  const auto r = run_lfd("camera calibrate " + path("0.png") + " " + path("1.png") + " " +
                         path("2.png") + " --out " + path("camera.yaml"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("only 3 of 3 photos"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("camera.yaml")));
}

TEST_F(CameraCli, PhotoWithoutTheBoardIsNamed) {
  ASSERT_EQ(run_lfd("camera board --out " + path("board.png") + " --square-px 40 --margin-mm 10")
                .exit_code, 0);
  photograph(path("board.png"), 20, 0, path("board_photo.png"));
  cv::imwrite(path("ceiling.png"), cv::Mat(480, 640, CV_8U, cv::Scalar(200)));
  const auto r = run_lfd("camera calibrate " + path("board_photo.png") + " " + path("ceiling.png") +
                         " --out " + path("camera.yaml"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("ceiling.png: no 9x6 ChArUco board found"), std::string::npos)
      << r.output;
}

TEST_F(CameraCli, BadBoardFlagsAndUnknownCommandsExitTwo) {
  EXPECT_EQ(run_lfd("camera board --out " + path("b.png") + " --squares 9").exit_code, 2);
  EXPECT_EQ(run_lfd("camera board --out " + path("b.png") + " --squares 2x6").exit_code, 2);
  EXPECT_EQ(run_lfd("camera").exit_code, 2);
  EXPECT_EQ(run_lfd("camera focus").exit_code, 2);
  EXPECT_EQ(run_lfd("camera --help").exit_code, 0);
}

}  // namespace
