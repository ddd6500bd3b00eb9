#include "sim/synthetic_unit.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <algorithm>

#include "display/lens_relations.hpp"

namespace lfd::sim {

SyntheticUnit make_synthetic_unit(const display::DisplayCalibration& real,
                                  const SyntheticUnitOptions& o) {
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  SyntheticUnit unit;
  unit.truth.display = real;
  unit.truth.display.source = nlohmann::ordered_json::object();
  unit.truth.display.view_cone_deg = real.view_cone_deg + o.view_cone_error_deg;
  // A smooth random warp on a coarse 5x5 grid (not the solver's grid), without the mean and
  // linear trend that belong to center, pitch and slope.
  if (o.warp_amplitude > 0) {
    std::vector<double> c(25);
    for (auto& x : c) x = uni(rng);
    display::CorrectionField w = display::remove_gauge(display::CorrectionField(5, 5, c));
    const auto r = w.range();
    const double scale = o.warp_amplitude / std::max(std::abs(r[0]), std::abs(r[1]));
    for (auto& x : w.coefficients()) x *= scale;
    unit.truth.correction = w;
  }
  unit.nominal.display = unit.truth.display;
  display::DisplayCalibration& n = unit.nominal.display;
  n.view_cone_deg = real.view_cone_deg;
  n.pitch_lpi = real.pitch_lpi * (1.0 + o.pitch_error_rel);
  n.slope = display::slope_of_slant_deg(display::slant_deg_of_slope(real.slope) + o.slant_error_deg);
  n.center_periods = 0.5 * (uni(rng) + 1.0);
  return unit;
}

CaptureRig make_capture_rig(const display::DisplayCalibration& d, int width_px, int positions, bool clean,
                            uint64_t seed, RigLayout layout) {
  CaptureRig rig;
  // The camera is turned to the screen's orientation (portrait screens, portrait photos), with
  // a moderately wide lens: the perspective of a large board is what fixes the camera's
  // lateral position, and with it the center (reference: docs/calibration.md).
  const bool portrait = d.screen_h > d.screen_w;
  const int height_px = portrait ? width_px * 4 / 3 : width_px * 3 / 4;
  const double fov_deg = 55.0;
  rig.intrinsics = CameraIntrinsics::from_fov(fov_deg, width_px, height_px);
  // Distance at which the screen spans 70 % of the image width (or height, if taller).
  const double tan_half = std::tan(fov_deg * std::numbers::pi / 360.0);
  const double span_w = d.width_m() / (0.7 * 2 * tan_half);
  const double span_h = d.height_m() / (0.7 * 2 * tan_half * height_px / width_px);
  const double dist = std::max(span_w, span_h);
  // Positions at clearly different distances separate the view cone from the pitch
  // (docs/calibration.md "How to photograph"); the closest one still sees the whole screen.
  const double lateral = 0.12 * dist;
  const double scale = dist / 0.45;
  const double tan30 = std::tan(std::numbers::pi / 6), tan25 = std::tan(25 * std::numbers::pi / 180);
  const std::vector<Eigen::Vector3d> spots =
      layout == RigLayout::kAboveBelow
          ? std::vector<Eigen::Vector3d>{{-0.06 * scale, 0.05 * scale, 0.45 * scale},
                                         {0.01 * scale, -0.04 * scale, 0.52 * scale},
                                         {0.07 * scale, 0.03 * scale, 0.60 * scale}}
      : layout == RigLayout::kOffAxis
          ? std::vector<Eigen::Vector3d>{{0.0, 0.02 * dist, 1.3 * dist},
                                         {tan30 * dist, -0.03 * dist, dist},
                                         {-tan25 * 1.6 * dist, 0.04 * dist, 1.6 * dist}}
          : std::vector<Eigen::Vector3d>{{0.0, 0.02 * dist, 1.3 * dist},
                                         {lateral, -0.03 * dist, dist},
                                         {-lateral, 0.04 * dist, 1.6 * dist}};
  for (int i = 0; i < positions; ++i) {
    CameraPose p;
    p.position_m = spots[size_t(i % 3)];
    p.look_at_m = {0.01 * dist * (i - 1), 0.0, 0.0};
    rig.poses.push_back(p);
  }
  CaptureEffects& e = rig.effects;
  e.seed = seed;
  e.supersample = 3;
  e.exposure = 0.7;  // white at ~70 % of full scale, as docs/calibration.md asks
  if (!clean) {
    rig.intrinsics.distortion = {-0.06, 0.02, 0.0, 0.0, 0.0};
    e.blur_px = 0.7;
    e.noise_sigma = 0.02;
    e.vignetting = 0.25;
    e.gamma = 2.2;
    e.glare_fraction = 0.05;
  }
  return rig;
}

double exposure_on_white(const DisplaySimulator& sim, const ImageF& white_panel,
                         const PhysicalCamera& camera, const CaptureEffects& effects) {
  CaptureEffects e = effects;
  e.exposure = 0.25;  // below clipping even for the brightest stripes
  e.noise_sigma = 0;
  e.glare_fraction = 0;
  const ImageF probe = sim.capture(white_panel, camera, e);
  std::vector<float> lit;
  for (float v : probe.pixels)
    if (v > 0.05f) lit.push_back(v);
  if (lit.empty()) return effects.exposure;
  std::nth_element(lit.begin(), lit.begin() + long(lit.size() * 0.99), lit.end());
  const double p99 = std::pow(double(lit[size_t(lit.size() * 0.99)]), e.gamma) / e.exposure;
  return std::pow(0.85, e.gamma) / p99;
}

CaptureEffects photo_effects(const CaptureRig& rig, size_t position, size_t photo) {
  CaptureEffects e = rig.effects;
  e.seed = rig.effects.seed * 1000003 + position * 101 + photo;
  e.glare_seed = rig.glare_moves ? 0 : rig.effects.seed * 1000003 + position * 101 + 7919;
  return e;
}

std::vector<PositionCaptures> simulate_captures(const PatternSet& set, const display::Calibration& truth,
                                                const CaptureRig& rig) {
  const DisplaySimulator sim(display::LensModel(truth.display, truth.correction));
  std::vector<PositionCaptures> out(rig.poses.size());
  for (size_t i = 0; i < rig.poses.size(); ++i) out[i].name = "pos" + std::to_string(i + 1);
  std::vector<double> exposure(rig.poses.size(), rig.effects.exposure);
  for (const auto& p : set.patterns) {
    if (p.kind != PatternKind::kWhite) continue;
    const ImageF panel = to_float(render_pattern(set, p));
    for (size_t i = 0; i < rig.poses.size(); ++i)
      exposure[i] = exposure_on_white(sim, panel, PhysicalCamera(rig.intrinsics, rig.poses[i]),
                                      rig.effects);
  }
  for (const auto& p : set.patterns) {
    const ImageF panel = to_float(render_pattern(set, p));
    const std::string stem = std::filesystem::path(p.file).stem().string();
    for (size_t i = 0; i < rig.poses.size(); ++i) {
      CaptureEffects e = photo_effects(rig, i, size_t(p.index));
      e.exposure = exposure[i];
      const PhysicalCamera camera(rig.intrinsics, rig.poses[i]);
      out[i].images[stem] = to_mat(sim.capture(panel, camera, e));
      out[i].paths[stem] = out[i].name + "/" + p.file;
    }
  }
  return out;
}

CalibrationErrors compare_with_truth(const display::Calibration& estimate, const display::Calibration& truth) {
  CalibrationErrors e;
  const display::LensModel est(estimate.display, estimate.correction);
  const display::LensModel tru(truth.display, truth.correction);
  e.slant_deg = std::abs(est.slant_deg() - tru.slant_deg());
  e.pitch_rel = std::abs(estimate.display.pitch_lpi / truth.display.pitch_lpi - 1.0);
  double dc = estimate.display.center_periods - truth.display.center_periods;
  dc -= std::round(dc);
  e.center_periods = std::abs(dc);
  e.view_cone_deg = std::abs(estimate.view_cone_measured_deg.value_or(
                                 estimate.display.view_cone_deg) -
                             truth.display.view_cone_deg);
  double sw = 0, sa = 0;
  const int n = 48;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      const double dw = estimate.correction(u, v) - truth.correction(u, v);
      double da = est.phase(u, v) - tru.phase(u, v);
      da -= std::round(da);
      sw += dw * dw;
      sa += da * da;
    }
  e.correction_rms_periods = std::sqrt(sw / (n * n));
  e.phase_rms_periods = std::sqrt(sa / (n * n));
  return e;
}

}  // namespace lfd::sim
