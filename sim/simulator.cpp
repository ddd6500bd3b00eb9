#include "sim/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <opencv2/calib3d.hpp>

#include "sim/camera_effects.hpp"
#include "display/cover_rays.hpp"
#include "display/lens_optics.hpp"
#include "util/error.hpp"

namespace lfd::sim {

namespace {

// Undistorted normalised image coordinates of the camera's pixel corners, (W + 1) x (H + 1),
// corner (i, j) at pixel position (i - 0.5, j - 0.5). Distortion is smooth, so samples inside
// a pixel interpolate bilinearly between its corners instead of inverting the distortion
// model millions of times.
std::vector<cv::Point2d> undistorted_corners(const CameraIntrinsics& k) {
  const int nx = k.width + 1, ny = k.height + 1;
  std::vector<cv::Point2d> corners(size_t(nx) * ny);
#pragma omp parallel for schedule(dynamic, 16)
  for (int j = 0; j < ny; ++j) {
    std::vector<cv::Point2d> in(nx), out;
    for (int i = 0; i < nx; ++i) in[i] = {i - 0.5, j - 0.5};
    cv::undistortPoints(in, out, cv::Mat(k.camera_matrix), k.distortion, cv::noArray(),
                        cv::noArray(),
                        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30,
                                         1e-12));
    std::copy(out.begin(), out.end(), corners.begin() + size_t(j) * nx);
  }
  return corners;
}

// The radiance() kernel for the last sigma this thread used: validation calls radiance()
// millions of times with one sigma, and building the table costs more than a call.
const display::PhaseKernel& cached_kernel(const display::LensModel& lens, double psf_sigma_phase) {
  thread_local std::unique_ptr<display::PhaseKernel> kernel;
  thread_local double box_u = -1, sigma_u = -1;
  const double b = 1.0 / (3.0 * lens.calibration().screen_w);
  const double s = std::max(0.0, psf_sigma_phase) / lens.pitch_periods();
  if (!kernel || b != box_u || s != sigma_u) {
    kernel = std::make_unique<display::PhaseKernel>(display::LensOptics::make_kernel(lens, psf_sigma_phase));
    box_u = b;
    sigma_u = s;
  }
  return *kernel;
}

}  // namespace

DisplaySimulator::DisplaySimulator(display::LensModel truth) : lens_(std::move(truth)) {}

std::array<float, 3> DisplaySimulator::radiance(const ImageF& panel, const Eigen::Vector3d& on_panel,
                                                const Eigen::Vector3d& eye,
                                                double psf_sigma_phase) const {
  display::check_panel_size(lens_, panel);
  const auto& c = lens_.calibration();
  const double u = on_panel.x() / c.width_m() + 0.5;
  const double v = on_panel.y() / c.height_m() + 0.5;
  const display::LensOptics optics(lens_, panel, cached_kernel(lens_, psf_sigma_phase));
  const Eigen::Vector3d d = eye - on_panel;
  return optics.seen_toward(u, v, d.x(), d.y(), d.z());
}

ImageF DisplaySimulator::capture(const ImageF& panel, const PhysicalCamera& camera,
                                 const CaptureEffects& effects) const {
  display::check_panel_size(lens_, panel);
  check_effects(effects);
  const CameraIntrinsics& k = camera.intrinsics();
  const Eigen::Vector3d c = camera.position();
  const auto& cal = lens_.calibration();
  const display::CoverLayer& cover = cal.cover;
  if (!(c.z() > cover.thickness_m))
    throw_input_error(
        "camera: position: z = {} m; the camera must be in front of the panel and its cover "
        "(z > {} m)", c.z(), cover.thickness_m);
  const double width_m = cal.width_m(), height_m = cal.height_m();
  const display::PhaseKernel kernel = display::LensOptics::make_kernel(lens_, effects.psf_sigma_phase);
  const display::LensOptics optics(lens_, panel, kernel);
  const Eigen::Matrix3d to_world = camera.rotation().transpose();

  const bool distorted = !k.distortion.empty() &&
                         std::any_of(k.distortion.begin(), k.distortion.end(),
                                     [](double d) { return d != 0.0; });
  const std::vector<cv::Point2d> corners = distorted ? undistorted_corners(k)
                                                     : std::vector<cv::Point2d>{};
  const int s = effects.supersample;
  const double fx = k.camera_matrix(0, 0), fy = k.camera_matrix(1, 1);
  const double skew = k.camera_matrix(0, 1);
  const double cx = k.camera_matrix(0, 2), cy = k.camera_matrix(1, 2);

  ImageF image(k.width, k.height, 3);
#pragma omp parallel for schedule(dynamic, 2)
  for (int y = 0; y < k.height; ++y) {
    float* row = image.row(y);
    for (int x = 0; x < k.width; ++x) {
      std::array<double, 3> sum{0, 0, 0};
      for (int sy = 0; sy < s; ++sy) {
        const double b = (sy + 0.5) / s;  // position inside the pixel footprint
        for (int sx = 0; sx < s; ++sx) {
          const double a = (sx + 0.5) / s;
          double xn, yn;
          if (distorted) {
            const size_t nx = size_t(k.width) + 1;
            const cv::Point2d& c00 = corners[size_t(y) * nx + x];
            const cv::Point2d& c10 = corners[size_t(y) * nx + x + 1];
            const cv::Point2d& c01 = corners[(size_t(y) + 1) * nx + x];
            const cv::Point2d& c11 = corners[(size_t(y) + 1) * nx + x + 1];
            xn = (1 - b) * ((1 - a) * c00.x + a * c10.x) + b * ((1 - a) * c01.x + a * c11.x);
            yn = (1 - b) * ((1 - a) * c00.y + a * c10.y) + b * ((1 - a) * c01.y + a * c11.y);
          } else {
            yn = (y - 0.5 + b - cy) / fy;
            xn = (x - 0.5 + a - cx - skew * yn) / fx;
          }
          const Eigen::Vector3d dir = to_world * Eigen::Vector3d(xn, yn, 1.0);
          std::array<float, 3> seen = effects.bezel;
          // The ray meets the panel plane z = 0 only if it travels toward it. It enters the
          // cover at z = t and crosses it at the steeper in-slab angle (Snell at the flat
          // face keeps the azimuth): the exact ray, traced from the camera's side.
          if (dir.z() < 0) {
            const display::PanelHit hit = display::panel_hit_through_cover({c.x(), c.y(), c.z()},
                                                         {dir.x(), dir.y(), dir.z()}, cover);
            const double u = hit.x / width_m + 0.5, v = hit.y / height_m + 0.5;
            if (u >= 0 && u <= 1 && v >= 0 && v <= 1)
              seen = optics.seen(u, v, hit.tan_x, hit.tan_y);
          }
          for (int ch = 0; ch < 3; ++ch) sum[ch] += seen[ch];
        }
      }
      const double inv = 1.0 / (s * s);
      for (int ch = 0; ch < 3; ++ch) row[x * 3 + ch] = float(sum[ch] * inv);
    }
  }
  apply_camera_effects(image, k, effects);
  return image;
}

}  // namespace lfd::sim
