#include "calib/camera/board_photographer.hpp"

#include <cmath>
#include <numbers>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace lfd::calib {

std::vector<BoardPose> tilted_poses() {
  return {{30, 0, 5, {0.01, 0, 0.42}},     {-30, 0, -5, {-0.01, 0.01, 0.42}},
          {0, 30, 3, {0, -0.01, 0.43}},    {0, -30, -3, {0.01, 0.01, 0.43}},
          {25, 25, 10, {0, 0, 0.45}},      {-25, 25, -8, {-0.01, 0, 0.45}},
          {25, -25, 0, {0.01, -0.01, 0.45}}, {-25, -25, 6, {0, 0.01, 0.45}}};
}

cv::Matx33d board_rotation(const BoardPose& p) {
  const double r = std::numbers::pi / 180;
  const double ax = p.about_x_deg * r, ay = p.about_y_deg * r, az = p.about_z_deg * r;
  const cv::Matx33d Rx(1, 0, 0, 0, std::cos(ax), -std::sin(ax), 0, std::sin(ax), std::cos(ax));
  const cv::Matx33d Ry(std::cos(ay), 0, std::sin(ay), 0, 1, 0, -std::sin(ay), 0, std::cos(ay));
  const cv::Matx33d Rz(std::cos(az), -std::sin(az), 0, std::sin(az), std::cos(az), 0, 0, 0, 1);
  return Rz * Ry * Rx;
}

BoardPhotographer::BoardPhotographer(const CameraBoardSpec& board, const KnownCamera& camera)
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

cv::Mat BoardPhotographer::photograph(const BoardPose& pose, uint64_t seed) const {
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

std::vector<CharucoCorners> detect_board_photos(const CameraBoardSpec& board,
                                                const KnownCamera& camera,
                                                const std::vector<BoardPose>& poses,
                                                uint64_t first_seed) {
  const BoardPhotographer photographer(board, camera);
  std::vector<CharucoCorners> out;
  for (size_t i = 0; i < poses.size(); ++i)
    out.push_back(detect_charuco_corners(photographer.photograph(poses[i], first_seed + i),
                                         board.make()));
  return out;
}

}  // namespace lfd::calib
