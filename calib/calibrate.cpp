#include "calib/calibrate.hpp"

#include <chrono>
#include <utility>

#include <cmath>

#include <fmt/format.h>

#include "calib/calibration_stages.hpp"
#include "calib/solve_plan.hpp"
#include "display/cover_layer.hpp"
#include "util/error.hpp"

namespace lfd::calib {

namespace {

using ojson = nlohmann::ordered_json;

// One distance cannot separate the view cone from the pitch: whether the known cone is kept or
// the result will be refused.
std::string one_position_warning(const sim::PatternSet& set) {
  return set.nominal.view_cone_measured_deg
             ? "one camera position: the view cone cannot be separated from the pitch; the known "
               "view cone is kept"
             : "one camera position: the view cone cannot be separated from the pitch and is not "
               "known; refused unless it is given (--view-cone) or the photos come from 2-3 "
               "positions at different distances";
}

}  // namespace

CoverGiven CoverGiven::range(double min_m, double max_m, double refractive_index, std::string said) {
  CoverGiven c;
  c.cover = {0.5 * (min_m + max_m), refractive_index};
  c.sigma_m = (max_m - min_m) / std::sqrt(12.0);  // a uniform distribution's
  c.said = std::move(said);
  return c;
}

CoverGiven CoverGiven::unknown(double refractive_index) {
  return range(0, kUnknownMaxM, refractive_index,
               fmt::format("unknown, 0-{:g} mm", 1e3 * kUnknownMaxM));
}

CoverGiven CoverGiven::of_description(const display::DisplayCalibration& nominal) {
  const display::CoverDefault family = display::cover_layer_for_family(nominal);
  CoverGiven c;
  c.cover = nominal.cover;
  if (family.family != "unknown" && nominal.cover.present() &&
      nominal.cover.thickness_m == family.cover.thickness_m &&
      nominal.cover.refractive_index == family.cover.refractive_index) {
    c.sigma_m = family.thickness_sigma_m;
    c.said = fmt::format("the {} family's estimate, {:g} +- {:g} mm", family.family,
                         1e3 * family.cover.thickness_m, 1e3 * family.thickness_sigma_m);
  } else {
    c.said = nominal.cover.present()
                 ? fmt::format("{:g} mm as described, held", 1e3 * nominal.cover.thickness_m)
                 : std::string("none as described, held");
  }
  return c;
}

void CalibrateOptions::check() const {
  const std::string where = "calibrate options";
  gates.check();
  require_field(max_motion_px > 0, where, "max_motion_px", "must be positive (pixels)");
  require_field(max_clipped_fraction > 0 && max_clipped_fraction <= 1, where,
                "max_clipped_fraction", "must lie in (0, 1]");
  require_field(min_contrast >= 0 && min_contrast < 1, where, "min_contrast",
                "must lie in [0, 1)");
  require_field(solver.grid_nx == 0 || solver.grid_nx >= 4, where, "solver.grid_nx",
                "must be 0 (no correction field) or at least 4 control points");
  require_field(solver.grid_ny == 0 || solver.grid_ny >= 4, where, "solver.grid_ny",
                "must be 0 (no correction field) or at least 4 control points");
  require_field(solver.max_samples_per_position > 0, where, "solver.max_samples_per_position",
                "must be positive");
  require_field(solver.threads > 0, where, "solver.threads", "must be positive");
  require_field(!view_cone_deg || (*view_cone_deg > 0 && *view_cone_deg < 180), where,
                "view_cone_deg", "must lie in (0, 180) degrees");
  if (cover) {
    require_field(cover->cover.thickness_m >= 0 && cover->cover.thickness_m < 1, where,
                  "cover.thickness_m", "must lie in [0, 1) metres");
    require_field(cover->sigma_m >= 0 && cover->sigma_m < 1, where, "cover.sigma_m",
                  "must lie in [0, 1) metres");
    require_field(cover->cover.refractive_index >= 1 && cover->cover.refractive_index < 4, where,
                  "cover.refractive_index", "must lie in [1, 4)");
  }
  require_field(solver.max_iterations > 0, where, "solver.max_iterations", "must be positive");
  for (auto [value, field] : {std::pair{solver.loss_scale, "solver.loss_scale"},
                              {solver.linear_loss_scale, "solver.linear_loss_scale"},
                              {solver.field_loss_scale, "solver.field_loss_scale"},
                              {solver.function_tolerance, "solver.function_tolerance"},
                              {solver.parameter_tolerance, "solver.parameter_tolerance"}})
    require_field(value > 0, where, field, "must be positive");
  require_field(solver.min_noise_samples >= 1, where, "solver.min_noise_samples",
                "must be at least 1 (the noise is a mean over them)");
  require_field(solver.min_cell_samples >= 1, where, "solver.min_cell_samples",
                "must be at least 1 (a cell's mean is over them)");
  require_field(solver.min_reciprocal_condition > 0 && solver.min_reciprocal_condition < 1, where,
                "solver.min_reciprocal_condition", "must lie in (0, 1)");
  require_field(min_board_corners >= 4, where, "min_board_corners",
                "must be at least 4 (a board pose needs 4 corners)");
  for (auto [value, field] : {std::pair{max_focal_sigma_rel, "max_focal_sigma_rel"},
                              {marker_search_fraction, "marker_search_fraction"},
                              {max_fringe_shift_periods, "max_fringe_shift_periods"}})
    require_field(value > 0, where, field, "must be positive");
  for (auto [value, field] : {std::pair{warn_self_calibration_rms_px, "warn_self_calibration_rms_px"},
                              {warn_board_rms_px, "warn_board_rms_px"},
                              {max_board_motion_px, "max_board_motion_px"},
                              {max_board_motion_diag_fraction, "max_board_motion_diag_fraction"},
                              {max_motion_diag_fraction, "max_motion_diag_fraction"},
                              {warn_exposure_change, "warn_exposure_change"},
                              {warn_row_variation, "warn_row_variation"}})
    require_field(value >= 0, where, field, "must not be negative");
  require_field(saturation_level > 0 && saturation_level <= 1, where, "saturation_level",
                "must lie in (0, 1] (of full scale)");
  require_field(min_step_correlation >= -1 && min_step_correlation <= 1, where,
                "min_step_correlation", "must lie in [-1, 1]");
  for (auto [value, field] : {std::pair{min_fringe_points, "min_fringe_points"},
                              {step_check_min_samples, "step_check_min_samples"}})
    require_field(value >= 0, where, field, "must not be negative");
  require_field(min_phase_samples >= 1, where, "min_phase_samples", "must be at least 1");
}

namespace {
// The controller: the stages of calibration_stages.hpp in order, for one solve.
CalibrationOutcome calibrate_stages(const sim::PatternSet& set,
                                    const std::vector<sim::PositionCaptures>& positions,
                                    const CalibrateOptions& options);
}  // namespace

CalibrationOutcome calibrate_display(const sim::PatternSet& set,
                                     const std::vector<sim::PositionCaptures>& positions,
                                     const CalibrateOptions& options) {
  const SolvePlan plan = plan_solves({set.nominal, positions.size()}, options);
  sim::PatternSet planned = set;
  planned.nominal = plan.nominal;
  CalibrationOutcome out;
  for (const PlannedSolve& solve : plan.solves) {
    if (solve.role != SolveRole::kConeMeasured) {
      out = calibrate_stages(planned, positions, plan.options);
      continue;
    }
    const CalibrationOutcome first = std::move(out);
    planned.nominal.display.view_cone_deg = first.calibration.display.view_cone_deg;
    out = calibrate_stages(planned, positions, plan.options);
    out.calibration.view_cone_nominal_deg = plan.nominal.display.view_cone_deg;  // the assumption
    out.seconds += first.seconds;
  }
  return out;
}

namespace {

CalibrationOutcome calibrate_stages(const sim::PatternSet& set,
                                    const std::vector<sim::PositionCaptures>& positions,
                                    const CalibrateOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  // The plan (solve_plan.hpp) resolved the cover and put its prior's mean into the nominal.
  const CoverGiven& cover = *options.cover;
  CalibrationOutcome out;
  out.cover_given = cover;
  const PatternRoles roles(set);

  const std::vector<BoardDetection> boards = detect_boards(set, roles, positions, options);
  choose_camera(options, boards, set, out);

  const LensShift shift(set.nominal);
  std::vector<PositionState> states(positions.size());
  auto context = [&](size_t i) {
    return PositionContext{set, roles, options, shift, positions[i], boards[i], out.camera,
                           out.warnings};
  };
  for (size_t i = 0; i < positions.size(); ++i) {
    const PositionContext ctx = context(i);
    PositionState& state = states[i];
    state.report.name = positions[i].name;
    register_position(ctx, state);
    check_exposure(ctx, state);
    identify_patterns(ctx, state);
    refine_with_fringes(ctx, state);
  }
  if (out.camera_self_calibrated) {
    // The boards alone leave the camera a few percent off (docs/calibration.md, 3.1,
    // "Without `--camera`"): refit it with the fringe points, then register again through it.
    refine_self_calibration(set, options, boards, states, out);
    for (size_t i = 0; i < positions.size(); ++i) {
      const PositionContext ctx = context(i);
      register_position(ctx, states[i]);
      refine_with_fringes(ctx, states[i]);
    }
  }
  std::vector<PositionData> data;
  std::vector<DecodedPhase> phases;  // kept for the colour-order check
  for (size_t i = 0; i < positions.size(); ++i) {
    const PositionContext ctx = context(i);
    DecodedPhase phase = decode_position_phase(ctx, states[i]);
    std::optional<Eigen::Vector3d> known;
    if (!options.known_camera_positions_m.empty()) known = options.known_camera_positions_m[i];
    data.push_back(position_data(ctx, states[i], phase, out.camera_self_calibrated, known));
    if (cover.sigma_m > 0) {
      add_cover_derivatives(ctx, states[i], data.back());
      if (known) data.back().camera_per_cover_m.setZero();  // known without registration
    }
    phases.push_back(std::move(phase));
    out.positions.push_back(states[i].report);
  }
  if (positions.size() < 2) out.warnings.push_back(one_position_warning(set));

  const sim::PatternSet solved = check_colour_order(set, options, phases, data, out);
  phases.clear();
  SolverOptions solver = options.solver;
  solver.cover_sigma_m = cover.sigma_m;
  solve_display(solved, data, solver, out);
  out.calibration = assemble_calibration(solved, positions, options, out);
  out.gate_failures = options.gates.evaluate(out.calibration, out.solve);
  if (out.colour_order.refused()) out.gate_failures.push_back(out.colour_order.finding);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

void enforce_gates(const CalibrationOutcome& outcome) {
  if (outcome.gate_failures.empty()) return;
  std::string msg = "calibration rejected by the quality gates (nothing written):";
  for (const auto& f : outcome.gate_failures) msg += "\n  - " + f;
  throw InputError(msg);
}

nlohmann::ordered_json cover_report(const CalibrationOutcome& o) {
  const CoverEstimate& c = o.solve.cover;
  ojson j = {{"given", o.cover_given.said},
             {"refractive_index", o.cover_given.cover.refractive_index},
             {"prior_thickness_m", o.cover_given.cover.thickness_m},
             {"prior_sigma_m", o.cover_given.sigma_m},
             {"thickness_m", c.free ? c.thickness_m : o.cover_given.cover.thickness_m},
             {"sigma_m", c.free ? c.sigma_m : 0.0},
             {"status", !c.free ? "held" : c.measured() ? "measured" : "assumed within its prior"}};
  if (c.free && std::isfinite(c.photos_sigma_m))
    j["photos"] = {{"thickness_m", c.photos_m},
                   {"sigma_m", c.photos_sigma_m},
                   {"disagreement_sigmas", c.disagreement_sigmas}};
  return j;
}

std::string cover_summary(const CalibrationOutcome& o) {
  const CoverEstimate& c = o.solve.cover;
  if (!c.free) return fmt::format("cover: {} (assumed; its error is not in the sigmas)", o.cover_given.said);
  const std::string photos =
      std::isfinite(c.photos_sigma_m)
          ? fmt::format("the photos alone say {:.1f} +- {:.1f} mm", 1e3 * c.photos_m,
                        1e3 * c.photos_sigma_m)
          : std::string("the photos do not tell it");
  return fmt::format("cover: {:.1f} +- {:.1f} mm, {} (given: {}; {}; its doubt is in every sigma)",
                     1e3 * c.thickness_m, 1e3 * c.sigma_m,
                     c.measured() ? "measured" : "assumed within its prior", o.cover_given.said,
                     photos);
}

nlohmann::ordered_json outcome_report(const CalibrationOutcome& o) {
  ojson j;
  j["calibration"] = to_json(o.calibration);
  j["coarse_start"] = {{"pitch_lpi", o.coarse.pitch_lpi},
                       {"slope", o.coarse.slope},
                       {"center_periods", o.coarse.center_periods},
                       {"view_cone_deg", o.coarse.view_cone_deg}};
  ojson positions = ojson::array();
  for (const auto& p : o.positions)
    positions.push_back(
        {{"name", p.name},
         {"board_corners", p.board_corners},
         {"fringe_points", p.fringe_points},
         {"reprojection_rms_px", p.reprojection_rms_px},
         {"camera_m", {p.camera_m.x(), p.camera_m.y(), p.camera_m.z()}},
         {"camera_refined_m",
          {p.camera_refined_m.x(), p.camera_refined_m.y(), p.camera_refined_m.z()}},
         {"phase_samples", p.samples},
         {"blocks", {{"on_screen", p.blocks_on_panel}, {"saturated", p.blocks_clipped},
                     {"low_modulation", p.blocks_low_modulation}}},
         {"median_modulation", p.median_modulation},
         {"white_clipped_fraction", p.clipped_fraction},
         {"plane_coherence", p.plane_coherence},
         {"residual_rms_periods", p.residual_rms_periods}});
  j["positions"] = positions;
  j["camera"] = {{"self_calibrated", o.camera_self_calibrated},
                 {"fx", o.camera.camera_matrix(0, 0)},
                 {"focal_sigma_rel", o.camera_focal_sigma_rel},
                 {"fy", o.camera.camera_matrix(1, 1)},
                 {"cx", o.camera.camera_matrix(0, 2)},
                 {"cy", o.camera.camera_matrix(1, 2)}};
  j["solver"] = {{"seconds", o.solve.solve_seconds},
                 {"phase_noise_periods", o.solve.obs_sigma_periods},
                 {"noise_inflation", o.solve.noise_inflation},
                 {"noise_inflation_cells", o.solve.noise_inflation_cells},
                 {"termination", o.solve.termination},
                 {"residual_robust_sigma_periods", o.solve.residual_robust_sigma_periods},
                 {"camera_shift_sigmas", o.solve.camera_shift_sigmas},
                 {"position_rms_periods", o.solve.position_rms},
                 {"position_rms_ratios", o.solve.position_rms_ratio},
                 {"stages", o.solve.report}};
  j["cover"] = cover_report(o);
  if (const FieldRefinement& f = o.solve.field_refinement; f.grid_nx > 0)
    j["solver"]["field_refinement"] = {{"grid", {f.grid_nx, f.grid_ny}},
                                       {"change", f.change},
                                       {"converged", f.converged},
                                       {"seconds", f.seconds}};
  j["colour_order"] = to_json(o.colour_order);
  j["warnings"] = o.warnings;
  j["gate_failures"] = o.gate_failures;
  j["seconds"] = o.seconds;
  return j;
}

}  // namespace lfd::calib
