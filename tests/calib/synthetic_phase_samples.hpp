#pragma once
// Decoded phase samples made straight from a known truth, without images: what the lens
// solver's model (calib/solver/lens_solver.hpp) says a camera at C decodes at panel point P,
//   psi(P) = f_seen(P) + s (A_true(X) - A_nom(X))  (mod 1),   s = +1 with invView, else -1,
//   f_seen(P) = seen_fraction_through_cover(Cx - Px, Cy - Py, Cz, cover, line_tilt_true, cone_true),
//   X = P + lens_content_shift / pitch',
// plus Gaussian noise. Shared by the solver and coarse-start tests.
#include <cmath>
#include <random>
#include <vector>

#include "display/lens_model.hpp"
#include "display/lens_relations.hpp"
#include "calib/solver/lens_solver.hpp"
#include "sim/synthetic_unit.hpp"

namespace lfd::calib::testing {

struct SyntheticPhaseOptions {
  int samples_u = 96, samples_v = 54;  // a jittered grid over the screen
  double noise_periods = 0.01;         // sample noise, lens periods
  double lateral_sigma_m = 0.001;      // registration error of the camera positions given to
  double depth_sigma_m = 0.003;        // the solver as priors (drawn, and stated as the priors)
  unsigned seed = 1;
};

struct SyntheticPhaseData {
  sim::SyntheticUnit unit;                    // truth (with its correction warp) and nominal
  std::vector<Eigen::Vector3d> cameras;  // true camera positions
  std::vector<PositionData> positions;   // samples + registration priors
};

// The noise-free phase a camera at `camera` decodes at physical panel point (u, v).
inline double synthetic_psi(const sim::SyntheticUnit& unit, const display::LensModel& truth,
                            const display::LensModel& nominal, const Eigen::Vector3d& camera, double u,
                            double v) {
  const display::DisplayCalibration& d = unit.truth.display;
  const double s = d.inv_view ? 1.0 : -1.0;
  const double px = (u - 0.5) * d.width_m(), py = (v - 0.5) * d.height_m();
  const double f_seen = display::seen_fraction_through_cover(camera.x() - px, camera.y() - py, camera.z(),
                                                    d.cover, truth.line_tilt(), d.view_cone_deg);
  const double content_u = u + display::lens_content_shift(f_seen, d.inv_view) / truth.pitch_periods();
  return f_seen + s * (truth.phase(content_u, v) - nominal.phase(content_u, v));
}

inline SyntheticPhaseData make_synthetic_phase_data(const display::DisplayCalibration& real,
                                                    const sim::SyntheticUnitOptions& unit_options,
                                                    const std::vector<Eigen::Vector3d>& cameras,
                                                    const SyntheticPhaseOptions& o = {}) {
  SyntheticPhaseData data;
  data.unit = sim::make_synthetic_unit(real, unit_options);
  data.cameras = cameras;
  const display::LensModel truth(data.unit.truth.display, data.unit.truth.correction);
  const display::LensModel nominal(data.unit.nominal.display, data.unit.nominal.correction);
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (size_t i = 0; i < cameras.size(); ++i) {
    PositionData p;
    p.name = "position ";
    p.name += std::to_string(i);
    for (int j = 0; j < o.samples_v; ++j)
      for (int k = 0; k < o.samples_u; ++k) {
        const double u = (k + jitter(rng)) / o.samples_u, v = (j + jitter(rng)) / o.samples_v;
        double psi = synthetic_psi(data.unit, truth, nominal, cameras[i], u, v) +
                     o.noise_periods * gauss(rng);
        psi -= std::floor(psi);
        p.samples.push_back({float(u), float(v), float(psi), 0.5f});
      }
    p.lateral_sigma_m = o.lateral_sigma_m;
    p.depth_sigma_m = o.depth_sigma_m;
    p.camera_m = cameras[i] + Eigen::Vector3d(o.lateral_sigma_m * gauss(rng), 0.0,
                                              o.depth_sigma_m * gauss(rng));
    // The height's registration error from its own stream, so x, z and the samples stay
    // those of the horizontal-only model.
    std::mt19937_64 height_rng(o.seed * 7919 + i);
    p.camera_m.y() += o.lateral_sigma_m * gauss(height_rng);
    data.positions.push_back(std::move(p));
  }
  return data;
}

// Three cameras where sim::make_capture_rig puts them: clearly different distances and
// sides, which separates the view cone from the pitch.
inline std::vector<Eigen::Vector3d> three_cameras(const display::DisplayCalibration& d) {
  std::vector<Eigen::Vector3d> cameras;
  for (const sim::CameraPose& pose : sim::make_capture_rig(d, 640, 3, true).poses)
    cameras.push_back(pose.position_m);
  return cameras;
}

}  // namespace lfd::calib::testing
