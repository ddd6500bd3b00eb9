#pragma once
// The quality gates a calibration must pass before it is written (docs/calibration.md section 3.5):
// the fit (convergence, residual over all samples with a robust scale, inliers), whether the
// positions agree (cameras near their registered poses, residuals alike), whether the view
// cone was measured or known, and the uncertainty of every estimated quantity.
// Each failure is one sentence with the measured value, the bound and what to change.
#include <string>
#include <vector>

#include "display/calibration_file.hpp"
#include "calib/solver/lens_solver.hpp"

namespace lfd::calib {

struct QualityGates {
  double max_residual_rms_periods = 0.08;  // ResidualStats::rms_periods (robust, all samples)
  double min_inlier_fraction = 0.6;
  // A refined camera this many registration sigmas from its registered position means the
  // registration or the model is wrong there (chi with 3 dof: 5 sigma has p ~ 1e-5).
  double max_camera_shift_sigmas = 5.0;
  // A position whose robust residual RMS exceeds that of the other positions pooled by this
  // factor disagrees with them (a camera that moved, glare, focus). Positions at different
  // distances differ in noise: 1.1-1.2 on the bench at 1280 px, 3.4 at 480 px.
  double max_position_rms_ratio = 4.0;
  double max_pitch_sigma_rel = 5e-5;   // the half-view tolerance's order, docs/calibration.md 3.5
  double max_slant_sigma_deg = 0.005;
  double max_center_sigma_periods = 0.01;
  double max_view_cone_sigma_deg = 2.0;
  double max_correction_sigma_periods = 0.02;
  // The photos' own estimate of the cover's thickness this many combined sigmas from the cover
  // given (CoverEstimate::disagreement_sigmas): the description is wrong, and a lens solved
  // through it is biased (docs/calibration.md, "The cover layer").
  double max_cover_disagreement_sigmas = 3.0;

  // The failed gates of a solved calibration (empty: it passed).
  std::vector<std::string> evaluate(const display::Calibration& calibration,
                                    const SolverResult& solve) const;
  // Throws InputError("quality gates: <field>: ...") for bounds that cannot gate anything.
  void check() const;
};

}  // namespace lfd::calib
