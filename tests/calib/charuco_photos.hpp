#pragma once
// Photographs of a printed ChArUco board taken by a known camera, for the camera-calibration
// tests: each output pixel's ray (distortion removed with the camera's own model) meets the
// board plane, and the rendered board is sampled there, at twice the resolution and then
// area-averaged, with a little seeded sensor noise.
#include <cmath>
#include <numbers>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "calib/camera/camera_calibration.hpp"

namespace lfd::calib::testing {

struct KnownCamera {
  cv::Size size{640, 480};
  cv::Matx33d K{600, 0, 322.5, 0, 603, 236.0, 0, 0, 1};
  std::vector<double> distortion{-0.15, 0.08, 0.0008, -0.0005, 0.0};
};

struct BoardPose {
  double about_x_deg = 0, about_y_deg = 0, about_z_deg = 0;  // board rotation
  cv::Vec3d centre_m{0, 0, 0.42};                            // board centre in camera axes
};

// Eight tilted poses, 25-30 deg both ways about both axes (the photographing guide's set).
inline std::vector<BoardPose> tilted_poses() {
  return {{30, 0, 5, {0.01, 0, 0.42}},     {-30, 0, -5, {-0.01, 0.01, 0.42}},
          {0, 30, 3, {0, -0.01, 0.43}},    {0, -30, -3, {0.01, 0.01, 0.43}},
          {25, 25, 10, {0, 0, 0.45}},      {-25, 25, -8, {-0.01, 0, 0.45}},
          {25, -25, 0, {0.01, -0.01, 0.45}}, {-25, -25, 6, {0, 0.01, 0.45}}};
}

inline cv::Matx33d board_rotation(const BoardPose& p) {
  const double r = std::numbers::pi / 180;
  const double ax = p.about_x_deg * r, ay = p.about_y_deg * r, az = p.about_z_deg * r;
  const cv::Matx33d Rx(1, 0, 0, 0, std::cos(ax), -std::sin(ax), 0, std::sin(ax), std::cos(ax));
  const cv::Matx33d Ry(std::cos(ay), 0, std::sin(ay), 0, 1, 0, -std::sin(ay), 0, std::cos(ay));
  const cv::Matx33d Rz(std::cos(az), -std::sin(az), 0, std::sin(az), std::cos(az), 0, 0, 0, 1);
  return Rz * Ry * Rx;
}

// Takes photos of `board` (printed with square_mm squares) with `camera`. The rays of the
// camera's pixels (distortion removed) are the same for every pose: found once.
class BoardPhotographer {
 public:
  static constexpr int kSupersample = 2;
  BoardPhotographer(const CameraBoardSpec& board, const KnownCamera& camera)
      : camera_(camera),
        print_(render_camera_board(board, kSquarePx, kMarginPx)),
        px_per_m_(kSquarePx / (board.square_mm / 1000.0)) {
    const int ss = kSupersample;
    const cv::Size big(camera.size.width * ss, camera.size.height * ss);
    std::vector<cv::Point2d> pixels;
    pixels.reserve(size_t(big.area()));
    for (int y = 0; y < big.height; ++y)
      for (int x = 0; x < big.width; ++x)
        pixels.emplace_back((x + 0.5) / ss - 0.5, (y + 0.5) / ss - 0.5);
    cv::undistortPoints(pixels, rays_, cv::Mat(camera.K), camera.distortion, cv::noArray(),
                        cv::noArray(),
                        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50,
                                         1e-12));
  }

  // An 8-bit grey photo at `pose`.
  cv::Mat photograph(const BoardPose& pose, uint64_t seed) const {
    // Board plane point (X, Y, 0), centred on the printed sheet, to normalised camera
    // coordinates: [r1 r2 t]; its inverse takes a ray back to the sheet.
    const cv::Matx33d R = board_rotation(pose);
    const cv::Matx33d H(R(0, 0), R(0, 1), pose.centre_m[0], R(1, 0), R(1, 1), pose.centre_m[1],
                        R(2, 0), R(2, 1), pose.centre_m[2]);
    const cv::Matx33d H_inv = H.inv();
    const cv::Size big(camera_.size.width * kSupersample, camera_.size.height * kSupersample);
    cv::Mat map_x(big, CV_32F), map_y(big, CV_32F);
    for (int y = 0; y < big.height; ++y)
      for (int x = 0; x < big.width; ++x) {
        const cv::Point2d& d = rays_[size_t(y) * size_t(big.width) + size_t(x)];
        const cv::Vec3d b = H_inv * cv::Vec3d(d.x, d.y, 1.0);
        map_x.at<float>(y, x) = float(b[0] / b[2] * px_per_m_ + 0.5 * print_.cols - 0.5);
        map_y.at<float>(y, x) = float(b[1] / b[2] * px_per_m_ + 0.5 * print_.rows - 0.5);
      }
    cv::Mat sampled, photo;
    cv::remap(print_, sampled, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT,
              cv::Scalar(90));
    cv::resize(sampled, photo, camera_.size, 0, 0, cv::INTER_AREA);
    // Paper is not white and ink not black; 1.5 levels of sensor noise.
    photo.convertTo(photo, CV_32F, 0.75, 30);
    cv::Mat noise(photo.size(), CV_32F);
    cv::RNG rng(seed);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.5);
    photo += noise;
    photo.convertTo(photo, CV_8U);
    return photo;
  }

 private:
  static constexpr int kSquarePx = 100, kMarginPx = 50;
  KnownCamera camera_;
  cv::Mat print_;
  double px_per_m_;
  std::vector<cv::Point2d> rays_;
};

}  // namespace lfd::calib::testing
