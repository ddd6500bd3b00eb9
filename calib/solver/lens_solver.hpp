#pragma once
// The lens solver (docs/calibration.md section 3.4): ONE non-linear least-squares problem over all
// camera positions. At a panel point P the camera looks at (from registration) the decoded
// phase is (docs/calibration.md section 3.2)
//   psi(P) = f_seen(P) + s (A_true(X) - A_nom(X))   (mod 1),  s = +1 with invView, -1 without
//   f_seen(P) = 0.5 + ((Cx - Px) + (Cy - Py) tilt W / H) / Cz / (2 tan(viewCone / 2)),
//   X = P + delta
// where X is the content the lens shows there and delta (< half a lens, horizontal) the mean
// offset to it (see lens_solver.cpp). Unknowns: pitch, slope,
// center, viewCone, the B-spline correction field w (smoothness prior; gauge: zero mean and
// zero linear trend, so it cannot absorb center, pitch or slope), per-position camera
// positions (priors from the registration) and, under its prior, the cover's thickness
// (SolverOptions::cover_sigma_m). Residuals are wrap-aware
// (wrap_to_[-0.5, 0.5](psi_obs - psi_model)) under a robust loss; uncertainties come from
// ceres::Covariance with the samples weighted by their measured noise, plus what a field of
// twice the resolution changes (SolverOptions::field_refinement).
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "display/calibration_file.hpp"
#include "calib/decoding/phase_decoding.hpp"
#include "util/default_display.hpp"

namespace lfd::calib {

struct PositionData {
  std::string name;
  std::vector<PhaseSample> samples;
  Eigen::Vector3d camera_m{0, 0, 0.6};  // from registration (display frame)
  double lateral_sigma_m = 0.001;        // prior on the registration's camera position (x, y)
  double depth_sigma_m = 0.003;
  // How the registered position moves per relative change of the camera's focal length
  // (d camera_m / (df / f)); used when the focal length is free (SolverOptions).
  Eigen::Vector3d camera_per_focal_m{0, 0, 0};
  // How the registered position, and each sample's panel point (u, v), move per metre of
  // cover thickness (registered again through a thicker cover); used when the thickness is
  // free (SolverOptions::cover_sigma_m). One per sample, or empty (they do not move).
  Eigen::Vector3d camera_per_cover_m{0, 0, 0};
  std::vector<Eigen::Vector2f> sample_per_cover;
};

struct LensEstimate {
  double pitch_lpi = 50, slope = -7, center_periods = 0, view_cone_deg = kDefaultViewConeDeg;
};

struct SolverOptions {
  int grid_nx = 8, grid_ny = 8;  // correction control points (0: no correction field)
  // Weight of the second differences of the control points, in the data's whitened units:
  // the prior residual is smoothness x (second difference) / (the stage's phase noise), so
  // prior and data keep the same balance in every stage (a second difference is a priori
  // N(0, noise / smoothness)).
  double smoothness = 0.02;
  double obs_sigma = 0.02;       // phase noise per sample assumed before it is measured, periods
  double loss_scale = 0.05;      // Cauchy scale of the final stage, lens periods
  double linear_loss_scale = 0.2;  // of the first stage (linear model): the warp it leaves out
                                   // is up to ~0.3 period, which must not count as outliers
  double field_loss_scale = 0.1;   // of the second stage, the correction field freed
  // A stage ends in CONVERGENCE (what the quality gates ask for) when the cost's relative change
  // or the step's falls below these (Ceres' function_tolerance, parameter_tolerance).
  double function_tolerance = 1e-10;
  double parameter_tolerance = 1e-12;
  int min_noise_samples = 10;  // inliers needed to measure the phase noise (else obs_sigma stays)
  int min_cell_samples = 10;   // inliers a screen cell needs to count in the noise's inflation
  // The covariance refuses (no sigmas) a Jacobian conditioned worse than this (Ceres'
  // min_reciprocal_condition_number): the problem is rank deficient there.
  double min_reciprocal_condition = 1e-14;
  bool fit_view_cone = true;     // needs >= 2 positions (else the nominal cone is kept)
  // The vertical offset across the slanted lens lines in f_seen (lens_relations.hpp); false
  // models the horizontal offset alone, only to measure what leaving it out costs.
  bool vertical_parallax = true;
  // A self-calibrated camera: its focal length is an unknown too, under this prior (relative
  // 1-sigma from the camera's calibration; 0: the camera is known). The phase alone hardly
  // fixes it (a longer focal length moves the cameras away, which a wider cone undoes), so
  // what it does is carry the camera's uncertainty into the view cone's sigma.
  double focal_sigma_rel = 0;
  // The cover layer's thickness as an unknown under a prior: the nominal's thickness (what
  // registration used) with this 1-sigma, metres; 0 holds it. Where the photos tell it (a
  // position well off axis, docs/calibration.md "The cover layer") it is estimated; where
  // they do not, the prior's spread reaches every other value's sigma through the covariance.
  double cover_sigma_m = 0;
  // After the solve, solve again on a grid with half the knot spacing (the same curvature
  // prior per unit of screen) and add each value's change to its sigma in quadrature: what the
  // grid cannot follow of a real warp leaves no residual, yet the positions' uneven coverage
  // of the screen turns it into a slant error (docs/calibration.md, "What the field's
  // resolution costs"). Doubles the solve time.
  bool field_refinement = true;
  int max_samples_per_position = 40000;
  int max_iterations = 200;  // per stage; the final one must end in CONVERGENCE
  int threads = 2;
  bool verbose = false;
};

// A phase residual beyond this is left out of the noise the final stage weights with and is
// drawn as an outlier in the report; the residual statistics the gates read cut at a multiple
// of the measured robust scale instead (residual_statistics.hpp).
inline constexpr double kOutlierBoundPeriods = 0.15;

// One phase sample after the solve (for reports): where it is, what was decoded, and the
// wrapped residual psi_obs - psi_model, lens periods.
struct ResidualSample {
  float u = 0, v = 0, psi = 0, residual = 0;
};

// The refined-grid solve's change of each value (SolverOptions::field_refinement), signed,
// same keys as SolverResult::sigma; empty when it did not run.
struct FieldRefinement {
  int grid_nx = 0, grid_ny = 0;
  std::map<std::string, double> change;
  bool converged = false;
  double seconds = 0;
};

// The cover's thickness as the solve saw it (SolverOptions::cover_sigma_m).
struct CoverEstimate {
  bool free = false;                          // false: held at prior_m
  double prior_m = 0, prior_sigma_m = 0;      // what was given
  double thickness_m = 0, sigma_m = 0;        // the solve's estimate and its 1-sigma
  // What the photos alone say (the solve's information less the prior's): their estimate
  // and 1-sigma (infinite: they say nothing), and how many of their and the prior's sigmas
  // combined the two lie apart.
  double photos_m = 0, photos_sigma_m = INFINITY;
  double disagreement_sigmas = 0;
  // The photos narrowed the prior to under this fraction of its sigma: the thickness counts
  // as measured, not assumed.
  static constexpr double kMeasuredFraction = 0.5;
  bool measured() const { return free && sigma_m < kMeasuredFraction * prior_sigma_m; }
};

struct SolverResult {
  LensEstimate lens;
  display::CorrectionField correction;
  std::vector<Eigen::Vector3d> cameras_m;
  double focal_change_rel = 0;  // the solve's relative change of the focal length (free only)
  CoverEstimate cover;
  // 1-sigma: pitch_lpi, slope, center_periods, ...: the covariance's, with the field
  // refinement's change added in quadrature when it ran.
  std::map<std::string, double> sigma;
  FieldRefinement field_refinement;
  display::ResidualStats residuals;              // of all samples, robust (residual_statistics.hpp)
  double residual_robust_sigma_periods = 0;  // 1.4826 MAD of all residuals
  std::vector<std::string> position_names;
  std::vector<double> position_rms;     // robust rms per position (its own scale), lens periods
  // Each position's robust rms over that of the other positions pooled (>= 2 positions).
  std::vector<double> position_rms_ratio;
  // How far each refined camera moved from its registered position, in the registration's
  // sigmas: |((x, y) / lateral sigma, z / depth sigma)|.
  std::vector<double> camera_shift_sigmas;
  std::vector<std::vector<ResidualSample>> position_samples;  // per position, as solved
  double obs_sigma_periods = 0;  // per-sample phase noise the final stage used (effective)
  double noise_inflation = 1;    // its inflation for errors shared by neighbouring samples
  int noise_inflation_cells = 0;  // the cells per side it was largest in (0: none above 1)
  double solve_seconds = 0;
  bool converged = false;       // the final stage ended in Ceres' CONVERGENCE
  std::string termination;      // the final stage's termination type and iterations
  bool view_cone_fitted = false;  // false: the start's (nominal) cone was held
  std::string report;                   // Ceres brief reports of the stages
};

SolverResult solve_lens(const display::Calibration& nominal, const LensEstimate& start,
                        const std::vector<PositionData>& positions, const SolverOptions& options);

// How far each refined camera lies from its registered position, in the registration's
// sigmas (PositionData::lateral_sigma_m for x and y, depth_sigma_m for z).
std::vector<double> camera_shifts_in_sigmas(const std::vector<PositionData>& positions,
                                            const std::vector<Eigen::Vector3d>& refined_m);

// Display calibration with the estimate's lens values.
display::DisplayCalibration apply_estimate(const display::DisplayCalibration& nominal, const LensEstimate& lens);

}  // namespace lfd::calib
