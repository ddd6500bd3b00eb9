#pragma once
// The report of `lfd calibrate --report DIR`, for the person who photographed the display:
// report.json (calib::outcome_report, plus the figure list), the figures
// (validate/calibration_figures.hpp) and a self-contained index.html with the result and its
// uncertainties, the quality gates (and what to change when one fails), warnings, a table per
// camera position and the solver's stages.
#include <filesystem>

#include "calib/calibrate.hpp"

namespace lfd::report {

// Writes the report into `dir` (created if needed), whether the calibration passed its gates
// or not: a rejected calibration is when the report is needed most. Every file is written
// atomically and index.html last, so a page never refers to a figure that is not there.
// Without gnuplot the page is written without figures and says so. Returns index.html's path.
std::filesystem::path write_calibration_report(const calib::CalibrationOutcome& outcome,
                                               const std::filesystem::path& dir);

}  // namespace lfd::report
