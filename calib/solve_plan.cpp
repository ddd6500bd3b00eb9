#include "calib/solve_plan.hpp"

#include "calib/undescribed.hpp"
#include "util/error.hpp"

namespace lfd::calib {

namespace {

// The positions the options speak of must be the photographed ones.
void check_positions(const PlanInputs& inputs, const CalibrateOptions& options) {
  if (inputs.positions == 0) throw_input_error("calibrate: no camera positions");
  if (!options.known_camera_positions_m.empty() &&
      options.known_camera_positions_m.size() != inputs.positions)
    throw_input_error("calibrate options: known_camera_positions_m: {} given for {} positions",
                      options.known_camera_positions_m.size(), inputs.positions);
}

// A view cone known by other means becomes the description's, marked as measured
// (assemble_calibration keeps it where the photos cannot measure it; the cone gate passes).
void adopt_known_view_cone(display::Calibration& n, double view_cone_deg) {
  n.view_cone_nominal_deg = n.view_cone_nominal_deg.value_or(n.display.view_cone_deg);
  n.view_cone_measured_deg = n.display.view_cone_deg = view_cone_deg;
}

// The cover's prior: as given, else nobody said what covers an undescribed panel's lenses
// (neither `lfd calibrate` nor `lfd patterns`): unknown, not none (docs/calibration.md, "An
// unknown cover"); else the description's (its family's estimate, or held as described).
CoverGiven resolve_cover(const display::Calibration& nominal, bool undescribed,
                         const CalibrateOptions& options) {
  if (options.cover) return *options.cover;
  if (undescribed && !assumptions_of(nominal).cover_given) return CoverGiven::unknown();
  return CoverGiven::of_description(nominal.display);
}

}  // namespace

SolvePlan plan_solves(const PlanInputs& inputs, const CalibrateOptions& options) {
  options.check();
  check_positions(inputs, options);
  SolvePlan plan;
  plan.nominal = inputs.nominal;
  plan.options = options;
  plan.undescribed = from_probes(inputs.nominal);
  if (options.view_cone_deg) adopt_known_view_cone(plan.nominal, *options.view_cone_deg);
  plan.options.view_cone_deg.reset();
  const bool cone_known = plan.nominal.view_cone_measured_deg.has_value();

  if (inputs.live && inputs.positions < 2 && options.camera && !cone_known)
    throw_input_error("--positions {}: one camera position cannot measure the view cone (the "
                      "pitch absorbs its error); give it with --view-cone, or use --positions 2 "
                      "or more at different distances",
                      inputs.positions);

  // Registration and the solve read the cover from the description: the prior's mean.
  const CoverGiven cover = resolve_cover(inputs.nominal, plan.undescribed, options);
  plan.nominal.display.cover = cover.cover;
  plan.options.cover = cover;

  // The subpixel order the probes read is a measurement too, which the photos confirm or
  // replace (docs/calibration.md, "A panel nobody described").
  if (plan.undescribed) plan.options.colour_order.estimate = true;

  const bool cone_measurable = inputs.positions >= 2 && options.solver.fit_view_cone;
  if (plan.undescribed && !cone_known && cone_measurable) {
    // Its view cone is assumed until the photos measure it, and registration's lens-shift
    // correction depends on it (docs/calibration.md, 3.1: up to half a lens per point, a
    // coarse sheet's 0.6 mm): registered and solved again with the cone the first measured.
    plan.solves = {{SolveRole::kConeAssumed,
                    "an undescribed panel's view cone is assumed: registered with the "
                    "assumption, which this solve measures"},
                   {SolveRole::kConeMeasured,
                    "registered and solved again with the view cone the first solve measured "
                    "(the lens-shift correction depends on it)"}};
  } else {
    plan.solves = {{SolveRole::kOnly,
                    cone_known       ? "the view cone is known (given or measured before): one solve"
                    : cone_measurable ? "the description's view cone registers well enough: one "
                                        "solve measures it"
                                      : "the view cone cannot be measured (one position, or "
                                        "not fitted): one solve with the description's"}};
  }
  return plan;
}

}  // namespace lfd::calib
