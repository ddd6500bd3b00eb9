#pragma once
// Calibration of a display unit from photographs (docs/calibration.md): the whole offline
// pipeline behind `lfd calibrate DIR`. Captures are checked before anything is estimated
// (missing or extra files, wrong pattern, camera motion, exposure, screen outside the photo,
// no board), then: registration -> phase decoding -> coarse start -> one Ceres solve ->
// quality gates, each a named stage (calibration_stages.hpp). Every failure is an InputError
// naming the file and what to change; nothing is written here (the caller writes the result
// only on success).
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"
#include "sim/capture_io.hpp"
#include "calib/decoding/colour_order.hpp"
#include "display/calibration_file.hpp"
#include "calib/solver/lens_solver.hpp"
#include "sim/patterns.hpp"
#include "calib/decoding/phase_decoding.hpp"
#include "calib/solver/quality_gates.hpp"

namespace lfd::calib {

// The cover layer in front of the lenses as given to the calibration (docs/calibration.md,
// "The cover layer"): a thickness with its 1-sigma (0: held, taken as measured), or a range,
// taken as a uniform prior's mean and standard deviation. Registration assumes the mean; the
// solve estimates the thickness where the photos tell it and otherwise carries the prior's
// spread into every sigma.
struct CoverGiven {
  display::CoverLayer cover;  // the thickness assumed (the prior's mean) and the index
  double sigma_m = 0;
  std::string said;           // how it was given, for the report
  // Unknown: 0-25 mm (the thickest block of a Looking Glass family, docs/display-model.md).
  static constexpr double kUnknownMaxM = 0.025;
  static CoverGiven range(double min_m, double max_m, double refractive_index, std::string said);
  static CoverGiven unknown(double refractive_index = display::CoverLayer{}.refractive_index);
  // The family's estimate (display/cover_layer.hpp) with its tolerance, when the set's cover is
  // its family's; else the set's cover held as described.
  static CoverGiven of_description(const display::DisplayCalibration& nominal);
};

struct CalibrateOptions {
  std::optional<sim::CameraIntrinsics> camera;  // else self-calibrated from >= 3 positions
  PhaseDecodeOptions decode;
  SolverOptions solver;
  QualityGates gates;
  // Camera positions known by other means (a measured rig; synthetic tests): they replace the
  // registration's, with 0.1 mm priors. One per position, or empty.
  std::vector<Eigen::Vector3d> known_camera_positions_m;
  // A view cone known by other means (`--view-cone`): it replaces the nominal's, stands in the
  // result where the photos cannot measure it (one position) and passes the cone gate. A
  // template whose view_cone_measured_deg is set counts as known too.
  std::optional<double> view_cone_deg;
  // The panel's subpixel order, when not the pattern set's (`--flip-subp`): the classic stride,
  // BGR (true) or RGB (false). The colour-order check compares it with the photos.
  std::optional<bool> flip_subp;
  // The cover layer, when not the description's (`--cover-thickness`, `--cover-unknown`,
  // `--cover-range`); unset: CoverGiven::of_description.
  std::optional<CoverGiven> cover;
  ColourOrderOptions colour_order;  // .estimate: `--estimate-colour-order`
  double max_motion_px = 3.0;          // corner markers may move this much between captures
                                       // (or 0.5 % of the image diagonal, if more)
  double max_clipped_fraction = 0.25;  // of the screen saturated in one capture
  double min_contrast = 0.06;          // white minus black, fraction of full scale

  // What the stages (calibration_stages.cpp) accept, refuse and warn about.
  int min_board_corners = 8;  // fewer ChArUco corners found: no usable board (the pose needs them)
  // A self-calibrated focal length less certain than this (relative, 1 sigma) is refused: it
  // would carry tens of percent into the view cone and center (choose_camera).
  double max_focal_sigma_rel = 0.10;
  double warn_self_calibration_rms_px = 1.0;  // worse: a --camera file would do better
  double warn_board_rms_px = 3.0;    // board reprojection error worse than this: focus?
  double saturation_level = 0.985;   // a screen pixel's brightest channel counts as clipped from here
  double marker_search_fraction = 0.1;  // of the image diagonal: a corner marker farther from
                                        // where the registration puts it is a false detection
  // Board capture vs the first marked capture: the corner markers may move this much plus a lens
  // of apparent shift plus this fraction of the image diagonal (the board pose's error).
  double max_board_motion_px = 4.0;
  double max_board_motion_diag_fraction = 0.01;
  double max_motion_diag_fraction = 0.005;  // max_motion_px's floor, of the image diagonal
  double max_fringe_shift_periods = 0.4;    // fringe blocks whose seen view is nearer its wrap
                                            // mix content a lens apart: left out
  int min_fringe_points = 100;     // fewer decoded fringe blocks: the board alone registers
  double min_step_correlation = 0.5;  // a phase photo correlating less is the wrong pattern
  int step_check_min_samples = 100;   // the correlation says nothing with fewer samples
  int min_phase_samples = 500;        // fewer per position: too little to solve with
  double warn_exposure_change = 0.02;  // exposure drift between the phase photos worth a warning
  double warn_row_variation = 0.01;    // banding along the rows (flicker) worth a warning

  // Throws InputError("calibrate options: <field>: ...") for values that cannot work.
  void check() const;
};

struct PositionReport {
  std::string name;
  int board_corners = 0;
  long fringe_points = 0;         // fringe blocks in the registration (0: board alone)
  double reprojection_rms_px = 0; // of all the registration's correspondences
  Eigen::Vector3d camera_m{0, 0, 0};          // registration
  Eigen::Vector3d camera_refined_m{0, 0, 0};  // after the solve
  long samples = 0;
  long blocks_on_panel = 0, blocks_clipped = 0, blocks_low_modulation = 0;
  double median_modulation = 0;
  double clipped_fraction = 0;
  double residual_rms_periods = 0;
  double plane_coherence = 0;
};

struct CalibrationOutcome {
  display::Calibration calibration;
  LensEstimate coarse;
  SolverResult solve;
  sim::CameraIntrinsics camera;
  bool camera_self_calibrated = false;
  // The self-calibrated focal length's relative 1-sigma uncertainty (0 for a given camera).
  double camera_focal_sigma_rel = 0;
  std::vector<PositionReport> positions;
  ColourOrderCheck colour_order;
  CoverGiven cover_given;  // the cover's prior; the solve's estimate is solve.cover
  std::vector<std::string> warnings;
  std::vector<std::string> gate_failures;  // empty when the calibration passed
  double seconds = 0;
};

// Runs the pipeline. Throws InputError for bad captures; returns gate failures in the outcome
// (see enforce_gates) so tools can still report what was measured.
CalibrationOutcome calibrate_display(const sim::PatternSet& set,
                                     const std::vector<sim::PositionCaptures>& positions,
                                     const CalibrateOptions& options);

// Throws InputError listing every failed gate and what to change.
void enforce_gates(const CalibrationOutcome& outcome);

// A JSON report: positions, coarse start, solver summary, cover, gates.
nlohmann::ordered_json outcome_report(const CalibrationOutcome& outcome);
// The cover: as given, as solved, what the photos alone say (report.json "cover"), and one
// line of it for the terminal.
nlohmann::ordered_json cover_report(const CalibrationOutcome& outcome);
std::string cover_summary(const CalibrationOutcome& outcome);

}  // namespace lfd::calib
