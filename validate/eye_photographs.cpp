#include "validate/eye_photographs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "display/lens_relations.hpp"
#include "interlace/interlacer.hpp"
#include "render/image_metrics.hpp"
#include "util/error.hpp"

namespace lfd::validate {

EyeBetweenViews eye_between_views(const display::LensModel& lens, int views, int view, double between) {
  if (views < 1) throw_input_error("eye between views: views: {} is not a view count", views);
  if (view < 0 || view >= views) throw_input_error("eye between views: view {} is outside 0..{}", view, views - 1);
  if (!(between >= 0.0 && between <= 1.0)) throw_input_error("eye between views: between: {} is outside [0, 1]", between);
  EyeBetweenViews e;
  e.view = view;
  e.between = between;
  e.fraction = (view + 0.5 + between) / views;
  if (!(e.fraction < 1.0))
    throw_input_error("eye between views: view {} + {} lies beyond the cone's last view centre", view, between);
  e.position_s = e.fraction - 0.5;
  const auto& cal = lens.calibration();
  const double distance = kEyeDistanceInPanelWidths * cal.width_m();
  const double tan_x = display::tan_of_seen_fraction(e.fraction, cal.view_cone_deg);
  // The direction in air picks the fraction; through a cover the eye's lateral offset is
  // tan_x times cover_seen_distance (display/lens_relations.hpp), a fixed point that contracts fast.
  double x = tan_x * distance;
  for (int i = 0; i < 8; ++i) x = tan_x * display::cover_seen_distance(x, 0.0, distance, cal.cover);
  e.eye = Eigen::Vector3d(x, 0.0, distance);
  return e;
}

ImageF single_view_panel(const display::LensModel& lens, const ImageF& view) {
  render::QuiltLayout one;
  one.cols = one.rows = one.views = 1;
  one.width = view.width;
  one.height = view.height;
  one.aspect = double(view.width) / view.height;
  return interlace::interlace(view, one, lens);
}

ImageF photograph(const sim::DisplaySimulator& simulator, const ImageF& panel, const EyeBetweenViews& eye,
                  int width_px, double psf_sigma_phase, int supersample) {
  const auto& cal = simulator.lens().calibration();
  const double seen_width = cal.width_m() * std::cos(std::atan2(eye.eye.x(), eye.eye.z()));
  const double fov_deg = 2.0 * std::atan(0.5 * seen_width / eye.eye.norm()) * 180.0 / std::numbers::pi;
  const int height_px = std::max(1, int(std::lround(width_px * cal.height_m() / seen_width)));
  sim::CameraPose pose;
  pose.position_m = eye.eye;
  pose.look_at_m = Eigen::Vector3d::Zero();
  const sim::PhysicalCamera camera(sim::CameraIntrinsics::from_fov(fov_deg, width_px, height_px), pose);
  sim::CaptureEffects effects;
  effects.psf_sigma_phase = psf_sigma_phase;
  effects.supersample = supersample;
  return simulator.capture(panel, camera, effects);
}

double photo_psnr(const ImageF& a, const ImageF& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw_input_error("photo psnr: photographs of {}x{} and {}x{}", a.width, a.height, b.width, b.height);
  const int x0 = a.width / 20, y0 = a.height / 20;
  const auto crop = [&](const ImageF& im) {
    ImageF out(a.width - 2 * x0, a.height - 2 * y0, a.channels);
    for (int y = 0; y < out.height; ++y)
      std::copy_n(im.row(y + y0) + size_t(x0) * a.channels, size_t(out.width) * a.channels, out.row(y));
    return out;
  };
  return render::psnr(crop(a), crop(b));
}

}  // namespace lfd::validate
