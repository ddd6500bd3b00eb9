#include "calib/registration/registration.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/aruco.hpp>
#include <opencv2/aruco/charuco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "calib/camera/charuco_detection.hpp"
#include "calib/camera/planar_camera_calibration.hpp"
#include "display/cover_rays.hpp"
#include "util/error.hpp"

namespace lfd::calib {

display::ScreenUV panel_px_to_uv(const display::DisplayCalibration& d, cv::Point2d px) {
  return {(px.x + 0.5) / d.screen_w, 1.0 - (px.y + 0.5) / d.screen_h};
}

Eigen::Vector3d uv_to_display_m(const display::DisplayCalibration& d, display::ScreenUV uv) {
  return {(uv.u - 0.5) * d.width_m(), (uv.v - 0.5) * d.height_m(), 0.0};
}

BoardDetection detect_board(const cv::Mat& gray8, const sim::PatternSet& set) {
  BoardDetection out;
  out.image_size = gray8.size();
  const CharucoCorners charuco = detect_charuco_corners(gray8, sim::make_board(set.board));
  out.markers = charuco.markers;
  out.image_px = charuco.image_px;
  out.ids = charuco.ids;
  // The lit screen (the board's white) reaching the image border means it is cut off; the
  // bezel and the room around it are dark.
  double max_value = 0;
  cv::minMaxLoc(gray8, nullptr, &max_value);
  // Per edge: a cut-off screen lights a long unbroken stretch of it; glare spots (several may
  // sit on one edge) only short ones.
  auto longest_lit_run = [&](cv::Mat line) {
    const cv::Mat lit = (line > 0.5 * max_value);
    const cv::Mat flat = lit.reshape(1, 1);
    int run = 0, best = 0;
    for (int i = 0; i < flat.cols; ++i) {
      run = flat.at<uint8_t>(0, i) ? run + 1 : 0;
      best = std::max(best, run);
    }
    return double(best) / double(line.total());
  };
  const double lit =
      std::max({longest_lit_run(gray8.row(0)), longest_lit_run(gray8.row(gray8.rows - 1)),
                longest_lit_run(gray8.col(0).clone()), longest_lit_run(gray8.col(gray8.cols - 1).clone())});
  out.touches_border = max_value > 20 && lit > 0.25;
  return out;
}

std::map<int, std::array<cv::Point2d, 4>> detect_corner_marker_corners(const cv::Mat& gray8) {
  std::vector<std::vector<cv::Point2f>> corners, rejected;
  std::vector<int> ids;
  auto params = cv::aruco::DetectorParameters::create();
  params->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
  cv::aruco::detectMarkers(gray8, sim::marker_dictionary(), corners, ids, params, rejected);
  std::map<int, std::array<cv::Point2d, 4>> out;
  for (size_t i = 0; i < ids.size(); ++i)
    for (int k = 0; k < 4; ++k) out[ids[i]][size_t(k)] = cv::Point2d(corners[i][size_t(k)]);
  return out;
}

std::map<int, cv::Point2d> detect_corner_markers(const cv::Mat& gray8) {
  std::map<int, cv::Point2d> out;
  for (const auto& [id, c] : detect_corner_marker_corners(gray8))
    out[id] = (c[0] + c[1] + c[2] + c[3]) * 0.25;
  return out;
}

namespace {

// Board corners as OpenCV object points in the display frame (metres, z = 0).
std::vector<cv::Point3f> object_points(const sim::PatternSet& set, const std::vector<int>& ids,
                                       const std::vector<cv::Point2d>& shift_px) {
  std::vector<cv::Point3f> out;
  for (size_t i = 0; i < ids.size(); ++i) {
    cv::Point2d px = set.board.corners_px.at(size_t(ids[i]));
    if (!shift_px.empty()) px += shift_px[i];
    const Eigen::Vector3d m = uv_to_display_m(set.nominal.display,
                                              panel_px_to_uv(set.nominal.display, px));
    out.emplace_back(float(m.x()), float(m.y()), 0.0f);
  }
  return out;
}

cv::Mat distortion_mat(const sim::CameraIntrinsics& c) {
  return c.distortion.empty() ? cv::Mat() : cv::Mat(c.distortion, true);
}

}  // namespace

sim::CameraIntrinsics self_calibrate(const std::vector<BoardDetection>& boards, const sim::PatternSet& set,
                                double* rms_px, double* focal_sigma_rel) {
  std::vector<std::vector<cv::Point3f>> objects;
  std::vector<std::vector<cv::Point2f>> images;
  cv::Size size;
  for (const auto& b : boards) {
    if (b.ids.size() < 6) continue;
    objects.push_back(object_points(set, b.ids, {}));
    images.push_back(b.image_px);
    size = b.image_size;
  }
  if (objects.size() < 3)
    throw_input_error(
        "self-calibration of the camera needs the board seen from at least 3 positions "
        "(found {}); photograph more positions or pass --camera camera.yaml",
        objects.size());
  // Planar views: k1, k2 only, which is what a handful of planar views can determine.
  std::vector<PlanarView> views;
  for (size_t i = 0; i < objects.size(); ++i) views.push_back({objects[i], images[i]});
  const PlanarCalibration c = calibrate_planar_views(views, size);
  if (rms_px) *rms_px = c.rms_px;
  if (focal_sigma_rel) *focal_sigma_rel = c.focal_sigma_rel;
  return c.camera;
}

Registration::Registration(const BoardDetection& board, const sim::PatternSet& set,
                           const sim::CameraIntrinsics& camera,
                           const std::vector<cv::Point2d>& panel_shift_px,
                           const ExtraPoints& extra)
    : camera_(camera), display_(set.nominal.display) {
  if (board.ids.size() < 8) throw InputError("too few board corners for registration");
  const cv::Mat K(camera_.camera_matrix), D = distortion_mat(camera_);

  std::vector<cv::Point2f> image_px = board.image_px;
  std::vector<cv::Point2d> panel_px, shift = panel_shift_px;
  for (int id : board.ids) panel_px.push_back(set.board.corners_px.at(size_t(id)));
  if (shift.size() != panel_px.size()) shift.assign(panel_px.size(), cv::Point2d(0, 0));
  for (size_t i = 0; i < extra.image_px.size(); ++i) {
    image_px.push_back(extra.image_px[i]);
    panel_px.push_back(extra.panel_px.at(i));
    shift.push_back(extra.shift_px.empty() ? cv::Point2d(0, 0) : extra.shift_px.at(i));
  }
  corners_ = int(image_px.size());

  std::vector<cv::Point2f> undistorted;
  cv::undistortPoints(image_px, undistorted, K, D, cv::noArray(), K);
  // The physical panel points (content moved back by the lens shift) are what a homography
  // maps the undistorted pixels to.
  std::vector<cv::Point2f> uv;
  for (size_t i = 0; i < panel_px.size(); ++i) {
    const display::ScreenUV p = panel_px_to_uv(display_, panel_px[i] + shift[i]);
    uv.emplace_back(float(p.u), float(p.v));
  }
  // Robust first (a corner misread on a glare spot), then least squares on the inliers.
  cv::Mat inliers;
  cv::Mat H = cv::findHomography(undistorted, uv, cv::RANSAC, 0.002, inliers);
  if (H.empty()) throw InputError("the board corners do not fit a homography");

  std::vector<cv::Point3f> obj_in;
  std::vector<cv::Point2f> img_in;
  for (int i = 0; i < corners_; ++i)
    if (inliers.at<uint8_t>(i)) {
      const Eigen::Vector3d m =
          uv_to_display_m(display_, panel_px_to_uv(display_, panel_px[size_t(i)] + shift[size_t(i)]));
      obj_in.emplace_back(float(m.x()), float(m.y()), 0.0f);
      img_in.push_back(image_px[size_t(i)]);
    }
  cv::solvePnP(obj_in, img_in, K, D, rvec_, tvec_, false, cv::SOLVEPNP_IPPE);
  cv::solvePnPRefineLM(obj_in, img_in, K, D, rvec_, tvec_);
  if (display_.cover.present()) {
    // The board is seen through the cover: each corner where its light leaves the cover's
    // front face toward the camera, which depends on where the camera is. The planar fit
    // above is the pose relative to the (paraxially) apparent panel; a few fixed-point steps
    // (exit points from the pose, pose from the exit points) give the pose in the display
    // frame, and the part of the refraction no pose can mimic stays out of it.
    const std::vector<cv::Point3f> on_panel = obj_in;
    for (int step = 0; step < 4; ++step) {
      cv::Matx33d R;
      cv::Rodrigues(rvec_, R);
      const cv::Vec3d c = -(R.t() * tvec_);
      for (size_t i = 0; i < on_panel.size(); ++i) {
        const display::Point3 e = display::cover_exit_point({on_panel[i].x, on_panel[i].y, 0.0},
                                          {c[0], c[1], c[2]}, display_.cover);
        obj_in[i] = cv::Point3f(float(e.x), float(e.y), float(e.z));
      }
      cv::solvePnPRefineLM(obj_in, img_in, K, D, rvec_, tvec_);
    }
  }
  std::vector<cv::Point2f> reproj;
  cv::projectPoints(obj_in, rvec_, tvec_, K, D, reproj);
  double sum = 0;
  for (size_t i = 0; i < reproj.size(); ++i) {
    const cv::Point2f d = reproj[i] - img_in[i];
    sum += d.dot(d);
  }
  reprojection_rms_px_ = std::sqrt(sum / std::max<size_t>(1, reproj.size()));
  cv::Matx33d R;
  cv::Rodrigues(rvec_, R);
  const cv::Vec3d c = -(R.t() * tvec_);
  position_m_ = {c[0], c[1], c[2]};
}

std::vector<display::ScreenUV> Registration::image_to_panel_uv(
    const std::vector<cv::Point2f>& image_px) const {
  std::vector<cv::Point2f> normalized;
  if (!image_px.empty())
    cv::undistortPoints(image_px, normalized, cv::Mat(camera_.camera_matrix),
                        distortion_mat(camera_));
  cv::Matx33d R;
  cv::Rodrigues(rvec_, R);
  const cv::Matx33d Rt = R.t();
  const cv::Vec3d centre = -(Rt * tvec_);
  std::vector<display::ScreenUV> out;
  out.reserve(normalized.size());
  for (const auto& p : normalized) {
    const cv::Vec3d ray = Rt * cv::Vec3d(p.x, p.y, 1.0);
    // The panel is the plane z = 0, behind the cover (if any): the refracted ray meets it.
    const display::PanelHit m = display::panel_hit_through_cover({centre[0], centre[1], centre[2]},
                                               {ray[0], ray[1], ray[2]}, display_.cover);
    out.push_back({m.x / display_.width_m() + 0.5, m.y / display_.height_m() + 0.5});
  }
  return out;
}

std::vector<cv::Point2d> Registration::uv_to_image(const std::vector<display::ScreenUV>& uv) const {
  cv::Matx33d R;
  cv::Rodrigues(rvec_, R);
  const cv::Vec3d c = -(R.t() * tvec_);
  std::vector<cv::Point3d> objects;
  for (const auto& p : uv) {
    const Eigen::Vector3d m = uv_to_display_m(display_, p);
    const display::Point3 e = display::cover_exit_point({m.x(), m.y(), 0.0}, {c[0], c[1], c[2]}, display_.cover);
    objects.emplace_back(e.x, e.y, e.z);
  }
  std::vector<cv::Point2d> out;
  if (!objects.empty())
    cv::projectPoints(objects, rvec_, tvec_, cv::Mat(camera_.camera_matrix),
                      distortion_mat(camera_), out);
  return out;
}

}  // namespace lfd::calib
