#include "report/calibration_figures.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "util/atomic_file.hpp"
#include "report/gnuplot.hpp"

namespace lfd::report {

namespace {

// psi is a phase: a cyclic palette, so 0.99 and 0.01 look alike as they are alike.
constexpr const char* kCyclicPalette =
    "set palette defined (0 '#e1d8e1', 0.25 '#5b6cb8', 0.5 '#2f1436', 0.75 '#b0573d', "
    "1 '#e1d8e1')\n";
// Residuals and the correction are signed: white at zero, blue and red for the two signs.
constexpr const char* kDivergingPalette =
    "set palette defined (0 '#3b4cc0', 0.5 '#f2f2f2', 1 '#b40426')\n";

constexpr double kHistogramBinPeriods = 0.005;

// Height over width of the screen, so that maps over (u, v) keep its shape.
double screen_ratio(const display::DisplayCalibration& d) {
  return d.screen_w > 0 && d.screen_h > 0 ? double(d.screen_h) / d.screen_w : 9.0 / 16.0;
}

// The start of every map: a canvas shaped like the screen, u right and v up.
std::string map_header(const std::string& png, double ratio, const std::string& title) {
  // Fixed margins (room for the colour box and its label) and a plot area 480 px wide: the
  // canvas height follows the screen's shape.
  const int height = int(std::clamp(120 + 480 * ratio, 360.0, 1000.0));
  std::string s = "reset\n";
  s += fmt::format("set terminal pngcairo size 680,{} font 'sans,10' noenhanced\n", height);
  s += fmt::format("set output '{}.tmp'\n", png);
  s += fmt::format("set size ratio {:.4f}\n", ratio);
  s += "set lmargin 10\nset rmargin 16\nset tmargin 3\nset bmargin 4\nunset key\n";
  s += "set xrange [0:1]\nset yrange [0:1]\nset tics out\n";
  s += "set xlabel 'u (0 = left edge of the screen, 1 = right)'\n";
  s += "set ylabel 'v (0 = bottom, 1 = top)'\n";
  s += fmt::format("set title {}\n", gnuplot_quote(title));
  return s;
}

// Marker size so that neighbouring samples (about one per decoding block) just touch.
double point_size(size_t samples, double ratio) {
  if (samples == 0) return 1.0;
  const double across = std::sqrt(double(samples) / ratio);
  return std::clamp(480.0 / across / 5.0, 0.12, 1.5);
}

std::string samples_data(const std::vector<calib::ResidualSample>& samples) {
  std::string s = "# u v psi residual (lens periods)\n";
  s.reserve(samples.size() * 36);
  for (const auto& p : samples)
    s += fmt::format("{:.5f} {:.5f} {:.5f} {:.5f}\n", p.u, p.v, p.psi, p.residual);
  return s;
}

std::string psi_script(const std::string& stem, const std::string& name, size_t samples,
                       double ratio) {
  std::string s = map_header(stem + "_psi.png", ratio,
                             fmt::format("{}: decoded phase psi ({} samples)", name, samples));
  s += kCyclicPalette;
  s += "set cbrange [0:1]\nset cblabel 'psi (lens periods, wrapped)'\n";
  s += fmt::format("plot '{}_samples.dat' using 1:2:3 with points pt 5 ps {:.2f} lc palette "
                   "notitle\nset output\n",
                   stem, point_size(samples, ratio));
  return s;
}

std::string residual_script(const std::string& stem, const std::string& name,
                            const std::vector<calib::ResidualSample>& samples, double rms,
                            double scale, double ratio) {
  const auto outliers = std::count_if(samples.begin(), samples.end(), [](const auto& p) {
    return std::abs(p.residual) >= kOutlierBoundPeriods;
  });
  std::string s = map_header(
      stem + "_residual.png", ratio,
      fmt::format("{}: phase residual, rms {:.4f} (inliers); {} outliers >= {} (black)",
                  name, rms, outliers, kOutlierBoundPeriods));
  s += kDivergingPalette;
  s += fmt::format("set cbrange [{0:.4f}:{1:.4f}]\nset cblabel 'residual (lens periods, "
                   "clipped at +-{1:.3f})'\n",
                   -scale, scale);
  // Inliers coloured; the solver's outliers drawn on top in black, so none hides.
  const double ps = point_size(samples.size(), ratio);
  s += fmt::format(
      "plot '{0}_samples.dat' using 1:2:(abs($4) < {1} ? $4 : 1/0) with points pt 5 ps {2:.2f} "
      "lc palette notitle, '{0}_samples.dat' using 1:(abs($4) >= {1} ? $2 : 1/0) with points "
      "pt 5 ps {2:.2f} lc rgb 'black' notitle\n"
      "set output\n",
      stem, kOutlierBoundPeriods, ps);
  return s;
}

std::string correction_data(const display::CorrectionField& field, double ratio) {
  const int nu = 120, nv = std::max(20, int(std::lround(120 * ratio)));
  std::string s = "# u v w (lens periods); one block per row of v\n";
  for (int j = 0; j < nv; ++j) {
    const double v = (j + 0.5) / nv;
    for (int i = 0; i < nu; ++i) {
      const double u = (i + 0.5) / nu;
      s += fmt::format("{:.5f} {:.5f} {:.6f}\n", u, v, field(u, v));
    }
    s += "\n";
  }
  return s;
}

std::string correction_script(const std::string& png, const calib::CalibrationOutcome& o,
                              double ratio) {
  const auto& c = o.calibration.correction;
  // The field's own range (as the page's table gives it), so the scale holds every value.
  const auto range = c.range();
  const double max_abs = std::max(std::abs(range[0]), std::abs(range[1]));
  const auto sigma = o.calibration.uncertainty.find("correction_rms_periods");
  std::string title = fmt::format("correction w(u, v), {}x{} control points: max |w| {:.3f}",
                                  c.nx(), c.ny(), max_abs);
  if (sigma != o.calibration.uncertainty.end())
    title += fmt::format(", 1-sigma {:.4f}", sigma->second);
  title += " (lens periods)";
  std::string s = map_header(png, ratio, title);
  s += kDivergingPalette;
  const double scale = std::max(max_abs, 1e-3);
  s += fmt::format("set cbrange [{:.5f}:{:.5f}]\nset cblabel 'w (lens periods)'\n", -scale, scale);
  s += "plot 'correction.dat' using 1:2:3 with image notitle\nset output\n";
  return s;
}

// Counts per bin over [-0.5, 0.5): all positions, then each position.
std::string histogram_data(const std::vector<std::vector<calib::ResidualSample>>& positions) {
  const int bins = int(std::lround(1.0 / kHistogramBinPeriods));
  std::vector<std::vector<long>> counts(positions.size() + 1, std::vector<long>(size_t(bins), 0));
  for (size_t i = 0; i < positions.size(); ++i)
    for (const auto& p : positions[i]) {
      if (!std::isfinite(p.residual)) continue;
      const int b = std::clamp(int(std::floor((p.residual + 0.5) / kHistogramBinPeriods)), 0,
                               bins - 1);
      ++counts[0][size_t(b)];
      ++counts[i + 1][size_t(b)];
    }
  std::string s = "# residual_bin_centre all position_1 .. position_N (counts)\n";
  for (int b = 0; b < bins; ++b) {
    s += fmt::format("{:.4f}", -0.5 + (b + 0.5) * kHistogramBinPeriods);
    for (const auto& c : counts) s += fmt::format(" {}", c[size_t(b)]);
    s += "\n";
  }
  return s;
}

std::string histogram_script(const std::string& png, const calib::CalibrationOutcome& o) {
  std::string s = "reset\nset terminal pngcairo size 900,480 font 'sans,10' noenhanced\n";
  s += fmt::format("set output '{}.tmp'\n", png);
  s += fmt::format("set title {}\n",
                   gnuplot_quote(fmt::format(
                       "phase residuals of all positions: rms {:.4f} lens periods (inliers), "
                       "{:.1f} % inliers, {} samples",
                       o.solve.residuals.rms_periods, 100 * o.solve.residuals.inlier_fraction,
                       o.solve.residuals.count)));
  // Logarithmic counts, so that a few outliers show beside thousands of inliers; empty bins
  // are drawn below the axis (clipped) rather than as a gap.
  s += "set logscale y\nset yrange [0.7:*]\nset grid\nset key top right\n";
  s += "set xrange [-0.5:0.5]\nset xlabel 'residual psi_obs - psi_model (lens periods, wrapped)'\n";
  s += fmt::format("set ylabel 'samples per {} lens period bin'\n", kHistogramBinPeriods);
  for (double x : {-kOutlierBoundPeriods, kOutlierBoundPeriods})
    s += fmt::format("set arrow from {0},graph 0 to {0},graph 1 nohead dt 2 lc rgb '#555555'\n",
                     x);
  s += fmt::format("set label 'outliers beyond +-{}' at graph 0.02,0.95\n", kOutlierBoundPeriods);
  s += "set style fill solid 0.35 noborder\n";
  s += fmt::format("plot 'residual_histogram.dat' using 1:($2 > 0 ? $2 : 0.1):({}) with boxes "
                   "lc rgb '#999999' title 'all positions'",
                   kHistogramBinPeriods);
  for (size_t i = 0; i < o.solve.position_samples.size(); ++i)
    s += fmt::format(", '' using 1:(${0} > 0 ? ${0} : 0.1) with histeps lw 1.5 title {1}", i + 3,
                     gnuplot_quote(i < o.positions.size() ? o.positions[i].name
                                                           : fmt::format("position {}", i + 1)));
  s += "\nset output\n";
  return s;
}

}  // namespace

std::string position_file_stem(size_t index, const std::string& name) {
  std::string safe;
  for (char c : name.substr(0, 40))
    safe += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return fmt::format("p{}_{}", index + 1, safe);
}

std::vector<std::string> figure_files(const CalibrationFigures& f) {
  std::vector<std::string> files;
  for (const auto& p : f.positions)
    for (const auto* name : {&p.psi, &p.residual})
      if (!name->empty()) files.push_back(*name);
  for (const auto* name : {&f.correction, &f.residual_histogram})
    if (!name->empty()) files.push_back(*name);
  return files;
}

CalibrationFigures draw_calibration_figures(const calib::CalibrationOutcome& o,
                                            const std::filesystem::path& dir) {
  CalibrationFigures figures;
  const double ratio = screen_ratio(o.calibration.display);
  // One colour scale for every position, so their maps compare; wide enough for the inliers'
  // spread, never wider than the outlier bound.
  figures.residual_scale_periods =
      std::clamp(4 * o.solve.residuals.rms_periods, 0.02, kOutlierBoundPeriods);
  std::string script;
  bool any_samples = false;
  for (size_t i = 0; i < o.positions.size(); ++i) {
    PositionFigures& pf = figures.positions.emplace_back();
    if (i >= o.solve.position_samples.size() || o.solve.position_samples[i].empty()) continue;
    const auto& samples = o.solve.position_samples[i];
    const std::string& name = o.positions[i].name;
    const std::string stem = position_file_stem(i, name);
    write_text_atomic(dir / (stem + "_samples.dat"), samples_data(samples));
    pf.psi = stem + "_psi.png";
    pf.residual = stem + "_residual.png";
    script += psi_script(stem, name, samples.size(), ratio);
    const double rms = i < o.solve.position_rms.size() ? o.solve.position_rms[i] : 0.0;
    script += residual_script(stem, name, samples, rms, figures.residual_scale_periods, ratio);
    any_samples = true;
  }
  if (!o.calibration.correction.empty()) {
    write_text_atomic(dir / "correction.dat", correction_data(o.calibration.correction, ratio));
    figures.correction = "correction.png";
    script += correction_script(figures.correction, o, ratio);
  }
  if (any_samples) {
    write_text_atomic(dir / "residual_histogram.dat", histogram_data(o.solve.position_samples));
    figures.residual_histogram = "residual_histogram.png";
    script += histogram_script(figures.residual_histogram, o);
  }
  const auto files = figure_files(figures);
  if (files.empty()) return figures;
  write_text_atomic(dir / "plots.gp", script);
  figures.drawn = run_gnuplot(dir, "plots.gp", files);
  return figures;
}

}  // namespace lfd::report
