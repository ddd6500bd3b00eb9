#include "pipeline/calibration_benchmark.hpp"

#include <cmath>

#include <fmt/format.h>

#include "calib/calibrate.hpp"
#include "display/cover_layer.hpp"
#include "display/visual_json.hpp"
#include "pipeline/capture_cache.hpp"
#include "calib/undescribed.hpp"
#include "sim/undescribed_units.hpp"
#include "util/error.hpp"
#include "util/stopwatch.hpp"

namespace lfd::pipeline {

const std::vector<BenchmarkDisplay>& benchmark_displays() {
  static const std::vector<BenchmarkDisplay> displays = {
      {"Gen1 8.9\"", "gen1-hid-00297.visual.json"},
      {"Portrait", "LKG-PORT-portrait.visual.json"},
      {"16\" Gen2", "LKG-APW92011.visual.json"},
      {"16\" Gen3 portrait", "template-16in-portrait-gen3.visual.json"}};
  return displays;
}

bool AccuracyBars::met_by(const sim::CalibrationErrors& e) const {
  return e.slant_deg <= slant_deg && e.pitch_rel <= pitch_rel && e.center_periods <= center &&
         e.view_cone_deg <= cone_deg && e.correction_rms_periods <= warp;
}

nlohmann::ordered_json AccuracyBars::to_json() const {
  return {{"slant_deg", slant_deg},
          {"pitch_rel", pitch_rel},
          {"center_periods", center},
          {"view_cone_deg", cone_deg},
          {"correction_rms_periods", warp}};
}

namespace {

// |error| / sigma per value; the pitch's error is relative, its sigma in lenticules per inch.
std::map<std::string, double> errors_over_sigmas(const sim::CalibrationErrors& e,
                                                 const std::map<std::string, double>& sigma,
                                                 double pitch_lpi) {
  std::map<std::string, double> out;
  auto add = [&](const char* name, const char* key, double error, double scale = 1.0) {
    const auto it = sigma.find(key);
    if (it != sigma.end() && it->second > 0) out[name] = std::abs(error) / (it->second * scale);
  };
  add("slant", "slant_deg", e.slant_deg);
  add("pitch", "pitch_lpi", e.pitch_rel, 1.0 / pitch_lpi);
  add("center", "center_periods", e.center_periods);
  add("cone", "view_cone_deg", e.view_cone_deg);
  add("warp", "correction_rms_periods", e.correction_rms_periods);
  return out;
}

}  // namespace

void CalibrationBenchmarkOptions::check() const {
  const std::string where = "calibration benchmark";
  require_field(width_px >= 320 && width_px <= 6000, where, "width_px", "must be in 320..6000");
  require_field(positions >= 1 && positions <= 3, where, "positions", "must be in 1..3");
  require_field(seeds >= 1 && seeds <= 20, where, "seeds", "must be in 1..20");
  require_field(supersample >= 1 && supersample <= 8, where, "supersample", "must be in 1..8");
  require_field(board_squares >= 3 && board_squares <= 20, where, "board_squares",
                "must be in 3..20");
  require_field(exposure_drift >= 0 && exposure_drift <= 0.2, where, "exposure_drift",
                "must be in 0..0.2");
  require_field(flicker >= 0 && flicker <= 0.2, where, "flicker", "must be in 0..0.2");
  require_field(flicker_bands > 0 && flicker_bands <= 100, where, "flicker_bands",
                "must be in (0, 100]");
}

nlohmann::ordered_json CalibrationBenchmarkRow::to_json() const {
  nlohmann::ordered_json row = {{"display", display}, {"file", file}, {"seed", seed},
                                {"positions", positions},
                                {"capture", {capture_width, capture_height}},
                                {"camera", camera_self_calibrated ? "self-calibrated" : "given"}};
  if (!errors) {
    row["error"] = failure;
    return row;
  }
  row["errors"] = {{"slant_deg", errors->slant_deg},
                   {"pitch_rel", errors->pitch_rel},
                   {"center_periods", errors->center_periods},
                   {"view_cone_deg", errors->view_cone_deg},
                   {"correction_rms_periods", errors->correction_rms_periods},
                   {"phase_rms_periods", errors->phase_rms_periods}};
  if (camera_self_calibrated)
    row["focal_length"] = {{"error_rel", focal_error_rel}, {"sigma_rel", focal_sigma_rel}};
  row["within_bars"] = within_bars;
  row["gate_failures"] = gate_failures;
  row["gate_values"] = gate_values;
  row["uncertainty"] = uncertainty;
  row["error_over_sigma"] = error_over_sigma;
  if (!probes.is_null()) row["probes"] = probes;
  if (!cover.is_null()) row["cover"] = cover;
  row["seconds"] = {{"simulate", simulate_s}, {"calibrate", calibrate_s}, {"solve", solve_s}};
  return row;
}

namespace {

// The photographer of one synthetic unit: the positions, and the effects the options switch
// on or off.
sim::CaptureRig benchmark_rig(const CalibrationBenchmarkOptions& o, const sim::SyntheticUnit& unit,
                                int seed) {
  sim::CaptureRig rig = sim::make_capture_rig(unit.truth.display, o.width_px,
                                                  o.positions, false, uint64_t(seed), o.layout);
  if (o.no_noise) rig.effects.noise_sigma = rig.effects.glare_fraction = 0;
  rig.glare_moves = o.moving_glare;
  rig.effects.exposure_drift = o.exposure_drift;
  rig.effects.flicker_amplitude = o.flicker;
  rig.effects.flicker_bands = o.flicker_bands;
  rig.effects.supersample = o.supersample;
  return rig;
}

// Every setting that changes the photos is in the cache key ("vp": the simulator with
// vertical parallax; captures cached before it are not reused).
std::string capture_cache_key(const CalibrationBenchmarkOptions& o, const BenchmarkDisplay& d,
                              int seed, const sim::PatternSet& set,
                              const sim::SyntheticUnit& unit) {
  const bool above_below = o.layout == sim::RigLayout::kAboveBelow;
  const bool off_axis = o.layout == sim::RigLayout::kOffAxis;
  const std::string key = fmt::format(
      "{}{}{}{}{}-vp-seed{}-w{}-p{}-ss{}-n{}", d.file, o.no_noise ? "-no-noise" : "",
      o.moving_glare ? "-moving-glare" : "", above_below ? "-above-below" : "",
      off_axis ? "-off-axis" : "", seed,
      o.width_px, o.positions, o.supersample, set.patterns.size());
  const std::string drift_key =
      o.exposure_drift > 0 ? fmt::format("-drift{}", o.exposure_drift) : "";
  const std::string flicker_key =
      o.flicker > 0 ? fmt::format("-flicker{}x{}", o.flicker, o.flicker_bands) : "";
  const display::CoverLayer& cover = unit.truth.display.cover;
  const std::string cover_key =
      cover.present() ? fmt::format("-cover{}n{}", cover.thickness_m, cover.refractive_index)
                      : "";
  return key + drift_key + flicker_key + cover_key;
}

// One row: the unit calibrated from its photographs (with the camera given or
// self-calibrated) and compared with its truth; a refusal is a row too.
CalibrationBenchmarkRow calibrate_row(const CalibrationBenchmarkOptions& o, const AccuracyBars& bars,
                                      const sim::PatternSet& set,
                                      const std::vector<sim::PositionCaptures>& captures,
                                      const sim::SyntheticUnit& unit, const sim::CaptureRig& rig,
                                      CalibrationBenchmarkRow row, bool self_calibrate) {
  row.camera_self_calibrated = self_calibrate;
  calib::CalibrateOptions options;
  if (!self_calibrate) options.camera = rig.intrinsics;
  options.decode.correct_exposure_drift = !o.no_exposure_fix;
  options.decode.exposure_row_gain = !o.no_row_exposure_fix;
  options.solver.vertical_parallax = !o.solver_without_vertical_parallax;
  if (o.cover_unknown) options.cover = calib::CoverGiven::unknown();
  if (o.true_poses)
    for (const auto& pose : rig.poses) options.known_camera_positions_m.push_back(pose.position_m);
  const Stopwatch stopwatch;
  try {
    const calib::CalibrationOutcome out = calib::calibrate_display(set, captures, options);
    row.calibrate_s = stopwatch.seconds();
    row.errors = sim::compare_with_truth(out.calibration, unit.truth);
    row.within_bars = bars.met_by(*row.errors);
    row.gate_failures = out.gate_failures;
    row.gate_values = {{"termination", out.solve.termination},
                       {"residual_rms_periods", out.solve.residuals.rms_periods},
                       {"inlier_fraction", out.solve.residuals.inlier_fraction},
                       {"camera_shift_sigmas", out.solve.camera_shift_sigmas},
                       {"position_rms_periods", out.solve.position_rms},
                       {"position_rms_ratios", out.solve.position_rms_ratio}};
    row.uncertainty = out.calibration.uncertainty;
    row.error_over_sigma = errors_over_sigmas(*row.errors, row.uncertainty,
                                              out.calibration.display.pitch_lpi);
    if (self_calibrate) {
      row.focal_error_rel = out.camera.camera_matrix(0, 0) / rig.intrinsics.camera_matrix(0, 0) - 1;
      row.focal_sigma_rel = out.camera_focal_sigma_rel;
    }
    row.solve_s = out.solve.solve_seconds;
    row.cover = calib::cover_report(out);
    row.cover["truth_m"] = unit.truth.display.cover.thickness_m;
    if (out.solve.cover.free && out.solve.cover.sigma_m > 0)
      row.error_over_sigma["cover"] =
          std::abs(out.solve.cover.thickness_m - unit.truth.display.cover.thickness_m) /
          out.solve.cover.sigma_m;
    for (size_t i = 0; i < out.positions.size(); ++i) {
      const Eigen::Vector3d t = rig.poses[i].position_m;
      row.poses.push_back({out.positions[i].name, t, out.positions[i].camera_m - t,
                           out.positions[i].camera_refined_m - t,
                           out.positions[i].residual_rms_periods});
    }
  } catch (const std::exception& ex) {
    row.failure = ex.what();
  }
  return row;
}

}  // namespace

// Per display kind and seed: a synthetic unit, its photographs (simulated or from the cache),
// then one row per camera mode.
namespace {

// What both camera modes' rows share.
CalibrationBenchmarkRow shared_row(const CalibrationBenchmarkOptions& o, const BenchmarkDisplay& d,
                                   int seed, const sim::CaptureRig& rig) {
  CalibrationBenchmarkRow row;
  row.display = d.label;
  row.file = d.file;
  row.seed = seed;
  row.positions = o.positions;
  row.capture_width = rig.intrinsics.width;
  row.capture_height = rig.intrinsics.height;
  return row;
}

// A panel nobody described: its probes from the first position, the fine set for the lens
// they find, one row per camera mode (a probe measurement that fails is a row too).
void run_undescribed(const CalibrationBenchmarkOptions& o, const AccuracyBars& bars,
                     const sim::UndescribedPanel& panel, int seed,
                     std::vector<CalibrationBenchmarkRow>& rows,
                     const std::function<void(const CalibrationBenchmarkRow&)>& on_row) {
  sim::SyntheticUnitOptions so;
  so.seed = uint64_t(seed);
  const sim::SyntheticUnit unit = sim::make_synthetic_unit(panel.display, so);
  const BenchmarkDisplay d{panel.label, "undescribed-" + std::to_string(std::hash<std::string>{}(panel.label) % 100000)};
  const auto& t = unit.truth.display;
  sim::PatternOptions po;
  po.board_squares_short = std::min(o.board_squares, 4);  // as `lfd patterns --screen` draws it
  const sim::PatternSet coarse = sim::plan_undescribed_patterns(t.screen_w, t.screen_h, t.dpi, po);
  const sim::CaptureRig rig = benchmark_rig(o, unit, seed);
  sim::CaptureRig first = rig;
  first.poses.resize(1);

  CalibrationBenchmarkRow measured = shared_row(o, d, seed, rig);
  const Stopwatch stopwatch;
  const auto coarse_captures = cached_captures(
      o.cache_dir, capture_cache_key(o, d, seed, coarse, unit) + "-probes", coarse, unit.truth, first);
  calib::ProbeRound found;
  try {
    found = calib::fine_set_from_probes(coarse, coarse_captures.front());
  } catch (const std::exception& ex) {
    measured.failure = std::string("probes: ") + ex.what();
    measured.simulate_s = stopwatch.seconds();
    if (on_row) on_row(measured);
    rows.push_back(measured);
    return;
  }
  const calib::ProbeLensEstimate& lens = found.lens;
  const double true_slant = display::slant_deg_of_slope(t.slope);
  measured.probes = {{"probes", coarse.probes.size()},
                     {"photos", coarse.patterns.size()},
                     {"pitch_lpi", lens.pitch_lpi},
                     {"pitch_rel_error", lens.pitch_lpi / t.pitch_lpi - 1},
                     {"slant_deg", lens.slant_deg},
                     {"slant_error_deg", lens.slant_deg - true_slant},
                     {"bgr", lens.bgr},
                     {"subpixel_order_right", lens.bgr == t.flip_subp},
                     {"probe", lens.chosen.probe},
                     {"strength", lens.chosen.strength}};
  const sim::PatternSet& fine = found.fine;
  // The fine set is drawn for what the probes found: that is in its key too.
  const std::string fine_key = fmt::format("{}-fine-lpi{:.6f}-slope{:.6f}-{}",
                                           capture_cache_key(o, d, seed, fine, unit),
                                           lens.pitch_lpi, lens.slope, lens.bgr ? "bgr" : "rgb");
  const auto captures = cached_captures(o.cache_dir, fine_key, fine, unit.truth, rig);
  measured.simulate_s = stopwatch.seconds();
  for (const bool self_calibrate : {false, true}) {
    if (self_calibrate && !o.self_calibrated) break;
    CalibrationBenchmarkRow row = calibrate_row(o, bars, fine, captures, unit, rig, measured, self_calibrate);
    if (on_row) on_row(row);
    rows.push_back(std::move(row));
  }
}

}  // namespace

std::vector<CalibrationBenchmarkRow> run_calibration_benchmark(
    const CalibrationBenchmarkOptions& o, const AccuracyBars& bars,
    const std::function<void(const CalibrationBenchmarkRow&)>& on_row) {
  o.check();
  std::vector<CalibrationBenchmarkRow> rows;
  if (o.undescribed) {
    for (const auto& panel : sim::undescribed_panels()) {
      if (!o.only.empty() && panel.label.find(o.only) == std::string::npos) continue;
      for (int seed = 1; seed <= o.seeds; ++seed) run_undescribed(o, bars, panel, seed, rows, on_row);
    }
    return rows;
  }
  for (const auto& d : benchmark_displays()) {
    if (!o.only.empty() && d.label.find(o.only) == std::string::npos) continue;
    auto real = display::read_visual_json(o.data_dir / "calibrations" / d.file);
    if (!o.bare_panels) real.cover = display::cover_layer_for_family(real).cover;
    for (int seed = 1; seed <= o.seeds; ++seed) {
      sim::SyntheticUnitOptions so;
      so.seed = uint64_t(seed);
      const sim::SyntheticUnit unit = sim::make_synthetic_unit(real, so);
      sim::PatternOptions po;
      po.board_squares_short = o.board_squares;
      sim::PatternSet set = sim::plan_patterns(unit.nominal, po);
      const sim::CaptureRig rig = benchmark_rig(o, unit, seed);

      CalibrationBenchmarkRow measured = shared_row(o, d, seed, rig);
      const Stopwatch stopwatch;
      const auto captures =
          cached_captures(o.cache_dir, capture_cache_key(o, d, seed, set, unit), set, unit.truth, rig);
      measured.simulate_s = stopwatch.seconds();
      // Registration and the solver read the cover from the nominal description.
      if (o.solver_without_cover) set.nominal.display.cover = display::CoverLayer{};

      for (const bool self_calibrate : {false, true}) {
        if (self_calibrate && !o.self_calibrated) break;
        CalibrationBenchmarkRow row = calibrate_row(o, bars, set, captures, unit, rig, measured, self_calibrate);
        if (on_row) on_row(row);
        rows.push_back(std::move(row));
      }
    }
  }
  return rows;
}

}  // namespace lfd::pipeline
