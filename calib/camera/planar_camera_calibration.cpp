#include "calib/camera/planar_camera_calibration.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>

namespace lfd::calib {

namespace {

// How much neighbouring correspondences share their reprojection errors (the lens shift
// left in them, blur, the distortion model): per view, the residuals are pooled in 16 x 16
// image cells; for independent errors a cell's mean of n has variance sigma^2 / n, so the
// mean of n |mean|^2 / sigma^2 over the cells is the factor by which the variance of
// anything fitted to them is too small (as calib/solver/lens_solver.cpp's measure_noise). >= 1.
double shared_error_inflation(const std::vector<PlanarView>& views, cv::Size size,
                              const cv::Mat& K, const cv::Mat& D,
                              const std::vector<cv::Mat>& rvecs,
                              const std::vector<cv::Mat>& tvecs) {
  constexpr int kCells = 16;
  double sum2 = 0, inflation_sum = 0;
  long n = 0, cells_used = 0;
  for (size_t i = 0; i < views.size(); ++i) {
    std::vector<cv::Point2f> projected;
    cv::projectPoints(views[i].panel_m, rvecs[i], tvecs[i], K, D, projected);
    std::vector<std::pair<cv::Point2d, long>> cells(kCells * kCells, {{0, 0}, 0});
    for (size_t k = 0; k < projected.size(); ++k) {
      const cv::Point2d r = projected[k] - views[i].image_px[k];
      sum2 += r.dot(r) / 2;  // per component
      ++n;
      const int cx = std::clamp(int(views[i].image_px[k].x * kCells / size.width), 0, kCells - 1);
      const int cy = std::clamp(int(views[i].image_px[k].y * kCells / size.height), 0, kCells - 1);
      cells[size_t(cy) * kCells + cx].first += r;
      cells[size_t(cy) * kCells + cx].second += 1;
    }
    for (const auto& [sum, count] : cells)
      if (count >= 5) {
        inflation_sum += sum.dot(sum) / 2 / double(count);
        ++cells_used;
      }
  }
  if (n < 10 || cells_used == 0 || sum2 <= 0) return 1.0;
  return std::max(1.0, inflation_sum / cells_used / (sum2 / double(n)));
}

}  // namespace

PlanarCalibration calibrate_planar_views(const std::vector<PlanarView>& views, cv::Size size,
                                         const sim::CameraIntrinsics* guess) {
  std::vector<std::vector<cv::Point3f>> objects;
  std::vector<std::vector<cv::Point2f>> images;
  long points = 0;
  for (const auto& v : views) {
    objects.push_back(v.panel_m);
    images.push_back(v.image_px);
    points += long(v.panel_m.size());
  }
  cv::Mat K, D;
  if (guess) {
    K = cv::Mat(guess->camera_matrix).clone();
    if (!guess->distortion.empty()) D = cv::Mat(guess->distortion, true).reshape(1, 1);
  } else {
    K = cv::initCameraMatrix2D(objects, images, size);
  }
  std::vector<cv::Mat> rvecs, tvecs;
  const int flags = cv::CALIB_USE_INTRINSIC_GUESS | cv::CALIB_ZERO_TANGENT_DIST | cv::CALIB_FIX_K3 |
                    cv::CALIB_FIX_ASPECT_RATIO;
  PlanarCalibration out;
  out.rms_px = cv::calibrateCamera(objects, images, size, K, D, rvecs, tvecs, flags);
  // Views nearly head-on leave f undetermined (it trades off against the distance and the
  // distortion); that must show instead of passing as a known camera.
  auto sum_sq_at = [&](double scale) {
    cv::Mat k = K.clone(), d = D.clone();
    k.at<double>(0, 0) *= scale;
    k.at<double>(1, 1) *= scale;
    std::vector<cv::Mat> r, t;
    const double e = cv::calibrateCamera(objects, images, size, k, d, r, t,
                                         flags | cv::CALIB_FIX_FOCAL_LENGTH);
    return double(points) * e * e;
  };
  const double h = 0.05, s0 = double(points) * out.rms_px * out.rms_px;
  const double curvature = (sum_sq_at(1 + h) + sum_sq_at(1 - h) - 2 * s0) / (h * h);
  // Correlated errors count as fewer independent points: thousands of fringe points would
  // otherwise claim a focal length several times more certain than it is.
  out.error_inflation = shared_error_inflation(views, size, K, D, rvecs, tvecs);
  out.focal_sigma_rel = curvature > 0
                            ? out.rms_px * std::sqrt(2.0 * out.error_inflation / curvature)
                            : INFINITY;
  out.camera.width = size.width;
  out.camera.height = size.height;
  out.camera.camera_matrix = cv::Matx33d(K);
  D.reshape(1, 1).copyTo(out.camera.distortion);
  return out;
}

}  // namespace lfd::calib
