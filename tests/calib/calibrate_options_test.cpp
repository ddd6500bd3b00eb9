// CalibrateOptions::check (calib/calibrate.hpp): the defaults pass; a threshold that cannot
// accept or refuse anything is refused, naming its field.
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "calib/calibrate.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

// The message of check()'s InputError, or "" when it passes.
std::string check_message(const std::function<void(CalibrateOptions&)>& change) {
  CalibrateOptions o;
  change(o);
  try {
    o.check();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CalibrateOptions, DefaultsPassTheCheck) { EXPECT_NO_THROW(CalibrateOptions{}.check()); }

TEST(CalibrateOptions, StageThresholdsThatCannotWorkAreRefusedByName) {
  const std::pair<const char*, std::function<void(CalibrateOptions&)>> cases[] = {
      {"min_board_corners", [](CalibrateOptions& o) { o.min_board_corners = 3; }},
      {"max_focal_sigma_rel", [](CalibrateOptions& o) { o.max_focal_sigma_rel = 0; }},
      {"warn_self_calibration_rms_px", [](CalibrateOptions& o) { o.warn_self_calibration_rms_px = -1; }},
      {"warn_board_rms_px", [](CalibrateOptions& o) { o.warn_board_rms_px = -1; }},
      {"saturation_level", [](CalibrateOptions& o) { o.saturation_level = 1.5; }},
      {"marker_search_fraction", [](CalibrateOptions& o) { o.marker_search_fraction = 0; }},
      {"max_board_motion_px", [](CalibrateOptions& o) { o.max_board_motion_px = -1; }},
      {"max_board_motion_diag_fraction", [](CalibrateOptions& o) { o.max_board_motion_diag_fraction = -0.1; }},
      {"max_motion_diag_fraction", [](CalibrateOptions& o) { o.max_motion_diag_fraction = -0.1; }},
      {"max_fringe_shift_periods", [](CalibrateOptions& o) { o.max_fringe_shift_periods = 0; }},
      {"min_fringe_points", [](CalibrateOptions& o) { o.min_fringe_points = -1; }},
      {"min_step_correlation", [](CalibrateOptions& o) { o.min_step_correlation = 2; }},
      {"step_check_min_samples", [](CalibrateOptions& o) { o.step_check_min_samples = -1; }},
      {"min_phase_samples", [](CalibrateOptions& o) { o.min_phase_samples = 0; }},
      {"warn_exposure_change", [](CalibrateOptions& o) { o.warn_exposure_change = -1; }},
      {"warn_row_variation", [](CalibrateOptions& o) { o.warn_row_variation = -1; }},
  };
  for (const auto& [field, change] : cases)
    EXPECT_NE(check_message(change).find(field), std::string::npos) << field;
}

TEST(CalibrateOptions, SolverThresholdsThatCannotWorkAreRefusedByName) {
  const std::pair<const char*, std::function<void(CalibrateOptions&)>> cases[] = {
      {"solver.linear_loss_scale", [](CalibrateOptions& o) { o.solver.linear_loss_scale = 0; }},
      {"solver.field_loss_scale", [](CalibrateOptions& o) { o.solver.field_loss_scale = -1; }},
      {"solver.function_tolerance", [](CalibrateOptions& o) { o.solver.function_tolerance = 0; }},
      {"solver.parameter_tolerance", [](CalibrateOptions& o) { o.solver.parameter_tolerance = 0; }},
      {"solver.min_noise_samples", [](CalibrateOptions& o) { o.solver.min_noise_samples = 0; }},
      {"solver.min_cell_samples", [](CalibrateOptions& o) { o.solver.min_cell_samples = 0; }},
      {"solver.min_reciprocal_condition", [](CalibrateOptions& o) { o.solver.min_reciprocal_condition = 0; }},
  };
  for (const auto& [field, change] : cases)
    EXPECT_NE(check_message(change).find(field), std::string::npos) << field;
}

}  // namespace
}  // namespace lfd::calib
