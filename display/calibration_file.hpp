#pragma once
// The project's calibration.json: a versioned superset of visual.json (docs/file-formats.md).
//   {"format": "lfd-calibration", "version": 1,
//    "display": {visual.json object},
//    "correction": {"nx":..,"ny":..,"coefficients":[..]} (lens periods, may be absent),
//    "view_cone_measured_deg": .., "view_cone_nominal_deg": .., "phase_blur_sigma": .. (lens periods),
//    "uncertainty": {"pitch_lpi":..,"slope":..,"center_periods":..,"view_cone_deg":..,"correction_rms_periods":..},
//    "residuals": {"rms_periods":..,"median_abs_periods":..,"inlier_fraction":..,"count":..},
//    "cover": {"thickness_m":..,"refractive_index":..} (the acrylic block or cover glass; absent: bare),
//    "recommended_views": N, "view_count_rule": "...",
//    "provenance": {"tool":..,"created":..,"method":..,"inputs":[..]}}
// Every field but "display" is optional. read_calibration() also accepts a plain visual.json.
// The measured view cone is the cone: display.viewCone holds it (also in memory), and the
// nominal cone it replaced is kept beside it for provenance.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "display/correction_field.hpp"
#include "display/display_calibration.hpp"

namespace lfd::display {

struct ResidualStats {
  double rms_periods = 0;
  double median_abs_periods = 0;
  double inlier_fraction = 1;
  long count = 0;
};

struct Calibration {
  DisplayCalibration display;
  CorrectionField correction;                 // empty for a plain visual.json
  std::optional<double> view_cone_measured_deg;  // when set, display.view_cone_deg equals it
  std::optional<double> view_cone_nominal_deg;   // the nominal cone before measurement
  std::optional<double> phase_blur_sigma;     // lens point spread, lens periods
  std::map<std::string, double> uncertainty;  // 1-sigma, keyed by parameter name
  std::optional<ResidualStats> residuals;
  std::optional<int> recommended_views;
  std::string view_count_rule;
  nlohmann::ordered_json provenance = nlohmann::ordered_json::object();
};

inline constexpr int kCalibrationFormatVersion = 1;

// Reads calibration.json or a plain visual.json (detected by the "format" field), validates
// every value (DisplayCalibration::check, correction grid size) and throws InputError naming
// the file and field.
Calibration read_calibration(const std::filesystem::path& path);
Calibration parse_calibration(const std::string& text, const std::string& name);
nlohmann::ordered_json to_json(const Calibration& calibration);
// Atomic write. Refuses to replace an existing file unless `force` (then keeps a .bak).
void write_calibration(const std::filesystem::path& path, const Calibration& calibration,
                       bool force);
// Exports the lens fields to visual.json; warns on stderr about what it cannot hold.
void export_visual_json(const std::filesystem::path& path, const Calibration& calibration,
                        bool force);

}  // namespace lfd::display
