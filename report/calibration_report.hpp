#pragma once
// The report of `lfd calibrate --report DIR`, for the person who photographed the display:
// report.json (calib::outcome_report, plus the figure list), the figures
// (validate/calibration_figures.hpp) and a self-contained index.html with the result and its
// uncertainties, the quality gates (and what to change when one fails), warnings, a table per
// camera position and the solver's stages.
#include <filesystem>
#include <string>

#include "calib/calibrate.hpp"

namespace lfd::report {

// A calibration of the same unit to compare the recovered one with (its factory calibration,
// from the device or a file), and what to call it on the page.
struct ReferenceCalibration {
  display::Calibration calibration;
  std::string name;  // e.g. "the factory calibration (device LKG-2K-04409)"
};

// Writes the report into `dir` (created if needed), whether the calibration passed its gates
// or not: a rejected calibration is when the report is needed most. Every file is written
// atomically and index.html last, so a page never refers to a figure that is not there.
// Without gnuplot the page is written without figures and says so. Returns index.html's path.
// With a `reference`, the page compares the recovered lens with it.
std::filesystem::path write_calibration_report(const calib::CalibrationOutcome& outcome,
                                               const std::filesystem::path& dir,
                                               const ReferenceCalibration* reference = nullptr);

}  // namespace lfd::report
