#pragma once
// What `calibrate_display` solves, decided before anything is measured (docs/calibration.md,
// "What is solved: the plan"): the options and the pattern set's description as given become
// the description registration starts from (a view cone known by other means, the cover's
// prior mean), the final options (the cover resolved, an undescribed panel's subpixel order to
// be checked by the photos), and one or two solves, each with its reason. Pure: no photo is
// read; combinations that cannot work are refused here, before any work.
#include <cstddef>
#include <string>
#include <vector>

#include "calib/calibrate.hpp"
#include "display/calibration_file.hpp"

namespace lfd::calib {

// What the photographs and their pattern set tell the plan.
struct PlanInputs {
  display::Calibration nominal;  // the pattern set's description (sim::PatternSet::nominal)
  size_t positions = 0;          // camera positions photographed (live: to be photographed)
  // A live session plans before anything is shown: a combination the gates would refuse
  // after every photo is taken is refused instead. Offline it is reported (warning, gate).
  bool live = false;
};

// Why a solve is run.
enum class SolveRole {
  kOnly,          // the description's view cone (nominal, given or measured) is good enough
  kConeAssumed,   // an undescribed panel: registered with the cone assumed, which it measures
  kConeMeasured,  // registered and solved again with the cone the solve before measured
};

struct PlannedSolve {
  SolveRole role = SolveRole::kOnly;
  std::string reason;  // one sentence, for people reading the plan (tests, logs)
};

struct SolvePlan {
  // What registration and the first solve start from: the set's description with the view
  // cone given (as measured, the nominal kept beside it) and the cover's prior mean.
  display::Calibration nominal;
  // The options the stages run with: the cover resolved (always set), view_cone_deg folded
  // into `nominal` (unset), an undescribed panel's colour order estimated.
  CalibrateOptions options;
  bool undescribed = false;  // the fine set of a panel nobody described (from_probes)
  std::vector<PlannedSolve> solves;  // one or two, in order
};

// The plan for `inputs` under `options`. Throws InputError for options that cannot work
// (CalibrateOptions::check), no positions, known camera positions that do not match the
// photographed ones, and (live) one position with a known camera and no known view cone.
SolvePlan plan_solves(const PlanInputs& inputs, const CalibrateOptions& options);

}  // namespace lfd::calib
