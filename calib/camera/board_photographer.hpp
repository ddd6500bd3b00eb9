#pragma once
// Photographs of a printed ChArUco board taken by a known camera, for the camera-calibration
// tests and `lfd bench camera-poses` (docs/calibration.md, "How many poses"): each output
// pixel's ray (distortion removed with the camera's own model) meets the board plane, and the
// rendered board is sampled there, at twice the resolution and then area-averaged, with a
// little seeded sensor noise.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "calib/camera/camera_calibration.hpp"

namespace lfd::calib {

// The camera of the measurements: 640x480, fx 600, fy 603 px, k1 -0.15, k2 0.08.
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
std::vector<BoardPose> tilted_poses();

cv::Matx33d board_rotation(const BoardPose& pose);

// Takes photos of `board` (printed with square_mm squares) with `camera`. The rays of the
// camera's pixels (distortion removed) are the same for every pose: found once.
class BoardPhotographer {
 public:
  static constexpr int kSupersample = 2;
  BoardPhotographer(const CameraBoardSpec& board, const KnownCamera& camera);

  // An 8-bit grey photo at `pose`.
  cv::Mat photograph(const BoardPose& pose, uint64_t seed) const;

 private:
  static constexpr int kSquarePx = 100, kMarginPx = 50;
  KnownCamera camera_;
  cv::Mat print_;
  double px_per_m_;
  std::vector<cv::Point2d> rays_;
};

// The board's corners detected in a photo at each of `poses` (photo i seeded `first_seed + i`).
std::vector<CharucoCorners> detect_board_photos(const CameraBoardSpec& board,
                                                const KnownCamera& camera,
                                                const std::vector<BoardPose>& poses,
                                                uint64_t first_seed = 17);

}  // namespace lfd::calib
