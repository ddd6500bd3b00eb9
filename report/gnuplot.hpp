#pragma once
// Figures are drawn by the gnuplot program, not by plotting code of our own: we write the
// data and a script, gnuplot writes PNGs (pngcairo); without gnuplot a report is written
// without figures (docs/calibration.md section 3.6).
#include <filesystem>
#include <string>
#include <vector>

namespace lfd::report {

// Runs `gnuplot script` in `dir`; every figure in `outputs` (file names in `dir`) must be
// written by the script to "<name>.tmp" and is renamed into place on success, so a failed
// run leaves no half-written figure. Returns false (after a warning on stderr) when gnuplot
// is missing or fails; the report is still useful without figures.
bool run_gnuplot(const std::filesystem::path& dir, const std::string& script_name,
                 const std::vector<std::string>& outputs);

// Quotes a string for a gnuplot single-quoted literal.
std::string gnuplot_quote(const std::string& text);

}  // namespace lfd::report
