#include "calib/camera/camera_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <opencv2/aruco.hpp>
#include <opencv2/calib3d.hpp>

#include "sim/capture_io.hpp"
#include "util/error.hpp"

namespace lfd::calib {

namespace {

// 5x5-bit markers survive the blur and the small size of a board at the far edge of a wide
// shot better than 4x4; 250 of them allow boards up to 22 x 22 squares.
constexpr auto kCameraBoardDictionary = cv::aruco::DICT_5X5_250;
constexpr int kCameraBoardMarkers = 250;

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

// How the board sat in one photo: its normal (turned toward the camera) in camera axes
// gives the tilt, tvec and the board centre the distance.
void measure_pose(const cv::Mat& rvec, const cv::Mat& tvec, const CameraBoardSpec& board,
                  CameraPhoto& photo) {
  cv::Matx33d R;
  cv::Rodrigues(rvec, R);
  cv::Vec3d n(R(0, 2), R(1, 2), R(2, 2));
  if (n[2] > 0) n = -n;
  photo.tilt_deg = deg(std::acos(std::min(1.0, -n[2])));
  photo.tilt_about_y_deg = deg(std::atan2(n[0], -n[2]));
  photo.tilt_about_x_deg = deg(std::atan2(n[1], -n[2]));
  const double m = board.square_mm / 1000.0;
  const cv::Vec3d centre_board(0.5 * board.squares_x * m, 0.5 * board.squares_y * m, 0);
  const cv::Vec3d centre = R * centre_board + cv::Vec3d(tvec.reshape(1, 3));
  photo.distance_mm = 1000.0 * cv::norm(centre);
}

// Empty when the usable poses determine the focal length; else what to photograph next.
std::string advise_poses(const CameraCalibration& c, double min_tilt_deg) {
  int tilted = 0;
  for (const auto& p : c.photos)
    if (p.usable && p.tilt_deg >= min_tilt_deg) ++tilted;
  if (tilted < 3)
    return fmt::format(
        "only {} photo(s) show the board tilted by {:.0f} deg or more: the focal length is "
        "poorly determined from boards seen head-on; add photos with the board turned 20-40 "
        "deg left, right, up and down",
        tilted, min_tilt_deg);
  std::vector<std::string> axes;
  if (c.tilt_range_y_deg < 2 * min_tilt_deg) axes.push_back("left/right (about the vertical)");
  if (c.tilt_range_x_deg < 2 * min_tilt_deg) axes.push_back("up/down (about the horizontal)");
  if (axes.empty()) return {};
  return fmt::format("the tilts span less than {:.0f} deg {}: add photos with the board turned "
                     "20-40 deg both ways",
                     2 * min_tilt_deg, axes.size() == 2 ? axes[0] + " and " + axes[1] : axes[0]);
}

}  // namespace

void CameraBoardSpec::check() const {
  if (squares_x < 3 || squares_y < 3)
    throw_input_error("board: {}x{} squares: needs at least 3 a side", squares_x, squares_y);
  if (squares_x * squares_y / 2 > kCameraBoardMarkers)
    throw_input_error("board: {}x{} squares need {} markers; the dictionary holds {}", squares_x,
                      squares_y, squares_x * squares_y / 2, kCameraBoardMarkers);
  if (!(square_mm > 0 && square_mm < 10000))
    throw_input_error("board: square size {} mm is not a length", square_mm);
  if (!(marker_ratio > 0.3 && marker_ratio < 0.9))
    throw_input_error("board: marker ratio {} (marker side / square side) must be in (0.3, 0.9)",
                      marker_ratio);
}

cv::Ptr<cv::aruco::CharucoBoard> CameraBoardSpec::make() const {
  check();
  const float square_m = float(square_mm / 1000.0);
  return cv::aruco::CharucoBoard::create(squares_x, squares_y, square_m,
                                         float(square_m * marker_ratio),
                                         cv::aruco::getPredefinedDictionary(kCameraBoardDictionary));
}

cv::Mat render_camera_board(const CameraBoardSpec& board, int square_px, int margin_px) {
  if (square_px < 20 || square_px > 2000)
    throw_input_error("board: {} pixels per square (20 to 2000)", square_px);
  if (margin_px < 0 || margin_px > 10000) throw_input_error("board: margin {} px", margin_px);
  cv::Mat img;
  board.make()->draw(cv::Size(board.squares_x * square_px + 2 * margin_px,
                              board.squares_y * square_px + 2 * margin_px),
                     img, margin_px, 1);
  return img;
}

void CameraCalibrationOptions::check() const {
  board.check();
  if (min_photos < 3) throw_input_error("min_photos: {} (a planar calibration needs >= 3)", min_photos);
  if (min_corners < 6) throw_input_error("min_corners: {} (needs >= 6)", min_corners);
  if (!(min_tilt_deg >= 0 && min_tilt_deg < 80))
    throw_input_error("min_tilt_deg: {} (0 to 80)", min_tilt_deg);
}

CameraCalibration calibrate_camera(const std::vector<CharucoCorners>& detections,
                                   const std::vector<std::string>& names, cv::Size image_size,
                                   const CameraCalibrationOptions& options) {
  options.check();
  CameraCalibration out;
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<std::vector<int>> ids;
  std::vector<size_t> used;  // photo index of each calibration view
  for (size_t i = 0; i < detections.size(); ++i) {
    CameraPhoto p;
    p.name = i < names.size() ? names[i] : fmt::format("photo {}", i + 1);
    p.markers = detections[i].markers;
    p.corners = int(detections[i].ids.size());
    p.usable = p.corners >= options.min_corners;
    if (p.usable) {
      corners.push_back(detections[i].image_px);
      ids.push_back(detections[i].ids);
      used.push_back(i);
    }
    out.photos.push_back(p);
  }
  out.usable = int(used.size());
  if (out.usable < options.min_photos)
    throw_input_error(
        "only {} of {} photos show the board with >= {} corners; the calibration needs {}: "
        "photograph the whole board from more tilted poses",
        out.usable, detections.size(), options.min_corners, options.min_photos);

  cv::Mat K, D, std_intrinsics, std_extrinsics, per_view;
  std::vector<cv::Mat> rvecs, tvecs;
  const int flags = options.fix_k3 ? cv::CALIB_FIX_K3 : 0;
  out.rms_px = cv::aruco::calibrateCameraCharuco(
      corners, ids, options.board.make(), image_size, K, D, rvecs, tvecs, std_intrinsics,
      std_extrinsics, per_view, flags,
      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-12));

  out.intrinsics.width = image_size.width;
  out.intrinsics.height = image_size.height;
  out.intrinsics.camera_matrix = cv::Matx33d(K);
  const int coefficients = options.fix_k3 ? 4 : 5;  // what the flags let vary
  for (int i = 0; i < coefficients; ++i) out.intrinsics.distortion.push_back(D.at<double>(i));
  // stdDeviationsIntrinsics: fx, fy, cx, cy, k1, ... (OpenCV's covariance at the solution).
  out.focal_sigma_rel = std_intrinsics.at<double>(0) / K.at<double>(0, 0);
  out.principal_sigma_px = std::max(std_intrinsics.at<double>(2), std_intrinsics.at<double>(3));

  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  for (size_t v = 0; v < used.size(); ++v) {
    CameraPhoto& p = out.photos[used[v]];
    p.rms_px = per_view.at<double>(int(v));
    measure_pose(rvecs[v], tvecs[v], options.board, p);
    min_x = std::min(min_x, p.tilt_about_x_deg), max_x = std::max(max_x, p.tilt_about_x_deg);
    min_y = std::min(min_y, p.tilt_about_y_deg), max_y = std::max(max_y, p.tilt_about_y_deg);
  }
  out.tilt_range_x_deg = max_x - min_x;
  out.tilt_range_y_deg = max_y - min_y;
  out.pose_advice = advise_poses(out, options.min_tilt_deg);
  return out;
}

CameraCalibration calibrate_camera_from_photos(const std::vector<std::filesystem::path>& photos,
                                               const CameraCalibrationOptions& options) {
  options.check();
  if (photos.empty()) throw_input_error("no photos given");
  const auto board = options.board.make();
  std::vector<CharucoCorners> detections;
  std::vector<std::string> names;
  cv::Size size;
  for (const auto& path : photos) {
    const std::string name = path.string();
    if (!std::filesystem::is_regular_file(path)) throw_input_error("{}: file not found", name);
    const cv::Mat gray = sim::to_gray8(sim::read_capture(path));
    if (size.empty()) size = gray.size();
    if (gray.size() != size)
      throw_input_error("{}: {}x{} pixels where the first photo has {}x{}: one camera, one "
                        "resolution and one orientation",
                        name, gray.cols, gray.rows, size.width, size.height);
    CharucoCorners found = detect_charuco_corners(gray, board);
    if (found.markers < 4)
      throw_input_error("{}: no {}x{} ChArUco board found ({} markers; print it with lfd camera "
                        "board and give the same --squares)",
                        name, options.board.squares_x, options.board.squares_y, found.markers);
    detections.push_back(std::move(found));
    names.push_back(name);
  }
  return calibrate_camera(detections, names, size, options);
}

}  // namespace lfd::calib
