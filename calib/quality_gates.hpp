#pragma once
// The quality gates a calibration must pass before it is written (DESIGN section 5 step 5):
// the fit (residual, inliers, convergence) and the uncertainty of every estimated quantity.
// Each failure is one sentence with the measured value, the bound and what to change.
#include <string>
#include <vector>

#include "calib/display/calibration_file.hpp"
#include "calib/lens_solver.hpp"

namespace lfd::calib {

struct QualityGates {
  double max_residual_rms_periods = 0.08;
  double min_inlier_fraction = 0.6;
  double max_pitch_sigma_rel = 5e-5;   // near the reference/display-optics.md 1.1 tolerance
  double max_slant_sigma_deg = 0.005;
  double max_center_sigma_periods = 0.01;
  double max_view_cone_sigma_deg = 2.0;
  double max_correction_sigma_periods = 0.02;

  // The failed gates of a solved calibration (empty: it passed).
  std::vector<std::string> evaluate(const Calibration& calibration,
                                    const SolverResult& solve) const;
  // Throws InputError("quality gates: <field>: ...") for bounds that cannot gate anything.
  void check() const;
};

}  // namespace lfd::calib
