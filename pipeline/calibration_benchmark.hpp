#pragma once
// The calibration benchmark's loop (docs/calibration.md, the accuracy matrix): for each display
// kind of the real calibrations, synthetic units (real values + a smooth warp, view cone
// +2 degrees) are photographed by the simulator from 1-3 positions while showing patterns made
// for a nominal description off by 1 % in pitch, 0.5 degree in slant and a random center; the
// `lfd calibrate` pipeline recovers them and each row holds the errors against the truth.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "sim/synthetic_unit.hpp"

namespace lfd::pipeline {

struct BenchmarkDisplay {
  std::string label;  // e.g. "Portrait"
  std::string file;   // calibrations/<file> under the data folder
};
// Gen1 8.9", Portrait, 16" Gen2, 16" Gen3 portrait.
const std::vector<BenchmarkDisplay>& benchmark_displays();

// The figures the calibration must reach.
struct AccuracyBars {
  double slant_deg = 0.001, pitch_rel = 2e-5, center = 0.005, cone_deg = 0.5, warp = 0.01;
  bool met_by(const sim::CalibrationErrors& e) const;
  nlohmann::ordered_json to_json() const;
};

struct CalibrationBenchmarkOptions {
  std::filesystem::path data_dir = "../shared/data";  // holds calibrations/*.visual.json
  int width_px = 1280;     // capture width
  int positions = 3;       // 1-3
  int seeds = 1;           // synthetic units per display kind
  int supersample = 2;     // simulator samples per camera pixel per axis
  int board_squares = 6;   // ChArUco squares along the short side
  std::string only;        // run only displays whose label contains this
  std::filesystem::path cache_dir;  // reuse simulated captures (empty: none)
  bool true_poses = false;    // diagnostic: give the solver the true camera positions
  // Each unit calibrated twice from the same photos: with the rig's camera given, then
  // self-calibrated (no camera file), one row each.
  bool self_calibrated = false;
  bool no_noise = false;      // diagnostic: no sensor noise and glare
  bool moving_glare = false;  // diagnostic: new glare in every photo
  double exposure_drift = 0;  // per-photo gain drift, relative 1-sigma (CaptureEffects)
  bool no_exposure_fix = false;  // decode without dividing the drift out (to compare)
  // Rolling-shutter flicker banding, relative amplitude (CaptureEffects::flicker_amplitude)
  // over `flicker_bands` bands of the image height.
  double flicker = 0;
  double flicker_bands = 2.5;
  bool no_row_exposure_fix = false;  // diagnostic: one gain per photo, no banding fit
  sim::RigLayout layout = sim::RigLayout::kSides;  // where the cameras stand
  // Diagnostic: solve with f_seen of the horizontal offset alone (captures keep the vertical
  // parallax), to measure what leaving it out costs.
  bool solver_without_vertical_parallax = false;
  // The units carry their family's cover layer (display/cover_layer.hpp) unless
  // `bare_panels`; `solver_without_cover` registers and solves as if the panel were bare
  // (photos keep the cover), to measure what ignoring it costs.
  bool bare_panels = false;
  bool solver_without_cover = false;
  // The calibration is told the cover is unknown (0-25 mm) instead of the family's estimate (or,
  // for a panel nobody described, none): the cover layer's honest case (docs/calibration.md, "An
  // unknown cover").
  bool cover_unknown = false;
  // Panels nobody described (sim/undescribed_units.hpp) instead of the shared calibrations:
  // the lens probes photographed from the first position, the fine set drawn for the lens
  // they find, then the same pipeline (docs/calibration.md, "A panel nobody described").
  bool undescribed = false;
  // Throws InputError("calibration benchmark: <field>: ...") for values out of range.
  void check() const;
};

struct PoseError {
  std::string name;
  Eigen::Vector3d truth_m, registration_error_m, refined_error_m;
  double residual_rms_periods = 0;
};

struct CalibrationBenchmarkRow {
  std::string display, file;
  int seed = 0, positions = 0;
  int capture_width = 0, capture_height = 0;
  bool camera_self_calibrated = false;
  double focal_error_rel = 0, focal_sigma_rel = 0;  // the self-calibrated focal length
  std::optional<sim::CalibrationErrors> errors;  // absent when the calibration failed
  std::string failure;                             // why, when it failed
  bool within_bars = false;
  std::vector<std::string> gate_failures;
  nlohmann::ordered_json gate_values;  // what the fit gates measured (calib/solver/quality_gates.hpp)
  std::map<std::string, double> uncertainty;
  // Each error over its reported 1-sigma (slant, pitch, center, cone, warp): whether the sigmas
  // cover the errors (docs/calibration.md, "With vertical parallax: cameras above and below the
  // centre"); absent where a sigma is missing or zero.
  std::map<std::string, double> error_over_sigma;
  std::vector<PoseError> poses;
  // Undescribed panels: what the probes found (pitch, slant, subpixel order) against the truth.
  nlohmann::ordered_json probes;
  // The cover: given, solved, what the photos alone say (calib::cover_report), and the truth.
  nlohmann::ordered_json cover;
  double simulate_s = 0, calibrate_s = 0, solve_s = 0;
  nlohmann::ordered_json to_json() const;
};

// Runs every display x seed; `on_row` sees each row as soon as it is measured.
std::vector<CalibrationBenchmarkRow> run_calibration_benchmark(
    const CalibrationBenchmarkOptions& options, const AccuracyBars& bars,
    const std::function<void(const CalibrationBenchmarkRow&)>& on_row = {});

}  // namespace lfd::pipeline
