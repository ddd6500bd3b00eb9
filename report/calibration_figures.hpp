#pragma once
// The figures of the calibration report (`lfd calibrate --report DIR`): per camera position the
// decoded phase psi and the solver's wrapped residual over the screen (u, v), the estimated
// correction field w(u, v), and a histogram of the residuals. We write the data and a gnuplot
// script; gnuplot draws the PNGs (validate/gnuplot.hpp), each renamed into place only when drawn.
#include <filesystem>
#include <string>
#include <vector>

#include "calib/calibrate.hpp"

namespace lfd::report {

// Residuals at or beyond the solver's inlier bound are drawn as outliers, so the figures show
// the samples its statistics leave out.
using calib::kOutlierBoundPeriods;

struct PositionFigures {
  std::string psi, residual;  // PNG file names in the report folder; empty without samples
};

struct CalibrationFigures {
  std::vector<PositionFigures> positions;  // one per outcome.positions entry
  std::string correction;                  // empty without a correction field
  std::string residual_histogram;          // empty without samples
  double residual_scale_periods = 0;       // half-range of the residual colour scale
  bool drawn = false;                      // false: gnuplot missing or failed, no figure
};

// A file-name stem for position `index` (0-based) named `name`: the folder name of a position
// may hold any character, the figures' names only letters, digits, '-' and '_'.
std::string position_file_stem(size_t index, const std::string& name);

// Writes the figures' data files and plots.gp into `dir` and runs gnuplot there. The names
// are filled in whether or not gnuplot drew them; `drawn` says whether it did.
CalibrationFigures draw_calibration_figures(const calib::CalibrationOutcome& outcome,
                                            const std::filesystem::path& dir);

// All PNG file names of `figures` (for checks and the page).
std::vector<std::string> figure_files(const CalibrationFigures& figures);

}  // namespace lfd::report
