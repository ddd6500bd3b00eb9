#include "report/calibration_report.hpp"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "display/lens_model.hpp"
#include "calib/solver/residual_statistics.hpp"
#include "util/atomic_file.hpp"
#include "report/calibration_figures.hpp"
#include "report/html.hpp"

namespace lfd::report {

namespace {

constexpr const char* kStyle =
    "<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;color:#222}"
    "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
    "text-align:right}td.l,th.l{text-align:left}img{max-width:100%;border:1px solid #ddd}"
    ".pass{background:#e6f4e6;border:1px solid #7b7;padding:0.6em 1em}"
    ".fail{background:#fbe9e7;border:1px solid #d77;padding:0.6em 1em}"
    ".warn{background:#fff6dd;border:1px solid #db5;padding:0.6em 1em}"
    ".pair{display:grid;grid-template-columns:1fr 1fr;gap:8px}"
    "figure{margin:0}figcaption{font-size:90%;color:#555}pre{background:#f6f6f6;padding:0.6em;"
    "overflow-x:auto;font-size:85%}</style>\n";

// "value +- sigma", or the value alone when the solve gave no uncertainty for it.
std::string with_sigma(double value, const display::Calibration& c, const char* key,
                       int decimals) {
  const auto it = c.uncertainty.find(key);
  if (it == c.uncertainty.end() || !std::isfinite(it->second))
    return fmt::format("{:.{}f}</td><td>n/a", value, decimals);
  return fmt::format("{:.{}f}</td><td>{:.{}g}", value, decimals, it->second, 2);
}

// Slant from vertical for a slope, as the lens model defines it.
double slant_deg(display::DisplayCalibration display, double slope) {
  display.slope = slope;
  return display::LensModel(display).slant_deg();
}

std::string xyz(const Eigen::Vector3d& p) {
  return fmt::format("{:+.4f}, {:+.4f}, {:.4f}", p.x(), p.y(), p.z());
}

// The recovered lens against a reference calibration of the same unit (its factory
// calibration, read from the device or a file): the difference, and in units of the recovered
// value's 1-sigma where the solve gave one.
std::string reference_section(const display::Calibration& c, const ReferenceCalibration& ref) {
  const display::DisplayCalibration& d = c.display;
  const display::DisplayCalibration& f = ref.calibration.display;
  auto row = [&](const char* name, double recovered, double factory, double difference,
                 const char* sigma_key, int decimals) {
    const auto it = c.uncertainty.find(sigma_key);
    const std::string in_sigmas =
        it != c.uncertainty.end() && it->second > 0 && std::isfinite(it->second)
            ? fmt::format("{:.1f}", difference / it->second)
            : std::string("n/a");
    return fmt::format("<tr><td class=\"l\">{}</td><td>{:.{}f}</td><td>{:.{}f}</td><td>{:+.{}f}"
                       "</td><td>{}</td></tr>\n",
                       name, factory, decimals, recovered, decimals, difference, decimals,
                       in_sigmas);
  };
  double center_difference = d.center_periods - f.center_periods;
  center_difference -= std::round(center_difference);  // the center is a phase, modulo 1
  std::string h = fmt::format(
      "<h2>Against {}</h2>\n<table><tr><th class=\"l\">parameter</th><th>reference</th>"
      "<th>recovered</th><th>difference</th><th>in 1-sigma</th></tr>\n",
      html_escape(ref.name));
  h += row("pitch (lenticules per inch)", d.pitch_lpi, f.pitch_lpi, d.pitch_lpi - f.pitch_lpi,
           "pitch_lpi", 5);
  h += row("slant from vertical (degrees)", slant_deg(d, d.slope), slant_deg(f, f.slope),
           slant_deg(d, d.slope) - slant_deg(f, f.slope), "slant_deg", 5);
  h += row("center (lens periods)", d.center_periods, f.center_periods, center_difference,
           "center_periods", 4);
  h += row("view cone (degrees)", d.view_cone_deg, f.view_cone_deg,
           d.view_cone_deg - f.view_cone_deg, "view_cone_deg", 2);
  h += "</table>\n<p>A difference of many sigmas means the unit has drifted from its reference "
       "(or the reference belongs to another unit); the recovered calibration is what the "
       "photographs show.</p>\n";
  return h;
}

std::string result_section(const calib::CalibrationOutcome& o) {
  const display::Calibration& c = o.calibration;
  const display::DisplayCalibration& d = c.display;
  std::string h = "<h2>Result</h2>\n<table><tr><th class=\"l\">parameter</th><th>value</th>"
                  "<th>1-sigma</th><th>coarse start</th></tr>\n";
  h += fmt::format("<tr><td class=\"l\">pitch (lenticules per inch)</td><td>{}</td><td>{:.5f}"
                   "</td></tr>\n",
                   with_sigma(d.pitch_lpi, c, "pitch_lpi", 5), o.coarse.pitch_lpi);
  h += fmt::format("<tr><td class=\"l\">slope</td><td>{}</td><td>{:.5f}</td></tr>\n",
                   with_sigma(d.slope, c, "slope", 5), o.coarse.slope);
  h += fmt::format("<tr><td class=\"l\">slant from vertical (degrees)</td><td>{}</td><td>{:.5f}"
                   "</td></tr>\n",
                   with_sigma(slant_deg(d, d.slope), c, "slant_deg", 5),
                   slant_deg(d, o.coarse.slope));
  h += fmt::format("<tr><td class=\"l\">center (lens periods)</td><td>{}</td><td>{:.4f}</td>"
                   "</tr>\n",
                   with_sigma(d.center_periods, c, "center_periods", 4), o.coarse.center_periods);
  if (c.view_cone_measured_deg)
    h += fmt::format("<tr><td class=\"l\">view cone (degrees, measured)</td><td>{}</td><td>{:.2f}"
                     "</td></tr>\n",
                     with_sigma(*c.view_cone_measured_deg, c, "view_cone_deg", 2),
                     o.coarse.view_cone_deg);
  else
    h += fmt::format("<tr><td class=\"l\">view cone (degrees, nominal kept: one position cannot "
                     "measure it)</td><td>{:.2f}</td><td>n/a</td><td>{:.2f}</td></tr>\n",
                     d.view_cone_deg, o.coarse.view_cone_deg);
  if (!c.correction.empty()) {
    const auto range = c.correction.range();
    const auto it = c.uncertainty.find("correction_rms_periods");
    h += fmt::format("<tr><td class=\"l\">correction field w ({}x{} control points), range "
                     "(lens periods)</td><td>{:+.4f} .. {:+.4f}</td><td>{}</td><td></td></tr>\n",
                     c.correction.nx(), c.correction.ny(), range[0], range[1],
                     it == c.uncertainty.end() ? std::string("n/a")
                                               : fmt::format("{:.2g} (rms over the screen)",
                                                             it->second));
  } else {
    h += "<tr><td class=\"l\">correction field</td><td>none (--grid 0)</td><td></td><td></td>"
         "</tr>\n";
  }
  // The cover: measured, assumed within its prior, or held (calib::cover_summary).
  h += fmt::format("<tr><td class=\"l\">cover layer</td><td colspan=\"3\">{}</td></tr>\n",
                   html_escape(calib::cover_summary(o)));
  const auto& r = o.solve.residuals;
  h += fmt::format("<tr><td class=\"l\">phase residual rms (lens periods, all samples within {} "
                   "robust sigmas)</td><td>{:.4f}</td><td></td><td></td></tr>\n<tr><td "
                   "class=\"l\">median |residual| (lens periods)</td><td>{:.4f}</td><td></td>"
                   "<td></td></tr>\n<tr><td class=\"l\">inliers (within {} robust sigmas = "
                   "{:.4f} lens periods)</td><td>{:.1f} % of {}</td><td></td><td></td></tr>\n",
                   calib::kOutlierCutSigmas, r.rms_periods, r.median_abs_periods,
                   calib::kOutlierCutSigmas,
                   calib::kOutlierCutSigmas * o.solve.residual_robust_sigma_periods,
                   100 * r.inlier_fraction, r.count);
  h += "</table>\n";
  if (c.recommended_views)
    h += fmt::format("<p><b>Recommended views: {}.</b> {}</p>\n", *c.recommended_views,
                     html_escape(c.view_count_rule));
  return h;
}

std::string gates_section(const calib::CalibrationOutcome& o) {
  std::string h = "<h2>Quality gates</h2>\n";
  if (o.gate_failures.empty())
    return h + "<p class=\"pass\">Every quality gate passed: the calibration can be written.</p>\n";
  h += fmt::format("<div class=\"fail\"><p><b>Rejected: {} gate{} failed, no calibration is "
                   "written.</b> Each line says what to change before photographing again.</p>"
                   "\n<ul>\n",
                   o.gate_failures.size(), o.gate_failures.size() == 1 ? "" : "s");
  for (const auto& f : o.gate_failures) h += "<li>" + html_escape(f) + "</li>\n";
  return h + "</ul></div>\n";
}

// The colour-order check's finding when it passed (a refusal is a gate, an adoption a warning).
std::string colour_order_section(const calib::CalibrationOutcome& o) {
  const calib::ColourOrderCheck& c = o.colour_order;
  if (!(c.best == c.given) || c.finding.empty()) return "";
  return "<p>" + html_escape(c.finding) + " (report.json: colour_order).</p>\n";
}

std::string warnings_section(const calib::CalibrationOutcome& o, bool figures_missing) {
  if (o.warnings.empty() && !figures_missing) return "";
  std::string h = "<h2>Warnings</h2>\n<div class=\"warn\"><ul>\n";
  for (const auto& w : o.warnings) h += "<li>" + html_escape(w) + "</li>\n";
  if (figures_missing)
    h += "<li>Figures not drawn: gnuplot is missing or failed (see <code>gnuplot.log</code>). "
         "Install gnuplot (Debian: <code>gnuplot-nox</code>) and run again.</li>\n";
  return h + "</ul></div>\n";
}

std::string positions_section(const calib::CalibrationOutcome& o) {
  std::string h =
      "<h2>Camera positions</h2>\n<table><tr><th class=\"l\">position</th><th>board corners</th>"
      "<th>fringe blocks</th><th>registration reprojection rms (px)</th><th>camera from registration x, y, z (m)</th>"
      "<th>camera refined x, y, z (m)</th><th>phase samples</th><th>blocks on screen</th>"
      "<th>saturated blocks</th><th>low-modulation blocks</th><th>median modulation</th>"
      "<th>white clipped</th><th>residual rms (lens periods)</th><th>plane coherence</th></tr>\n";
  for (const auto& p : o.positions)
    h += fmt::format(
        "<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{:.2f}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.2f}</td><td>{:.1f} %</td>"
        "<td>{:.4f}</td><td>{:.3f}</td></tr>\n",
        html_escape(p.name), p.board_corners, p.fringe_points, p.reprojection_rms_px,
        xyz(p.camera_m), xyz(p.camera_refined_m), p.samples, p.blocks_on_panel, p.blocks_clipped,
        p.blocks_low_modulation, p.median_modulation, 100 * p.clipped_fraction,
        p.residual_rms_periods, p.plane_coherence);
  h += "</table>\n<p>Display frame: panel at z = 0, x right, y up, origin at the panel centre. "
       "Plane coherence: how well one phase plane explains a position's decoded phase in the "
       "coarse start (1 = perfectly).</p>\n";
  return h;
}

std::string figure(const std::string& file, const std::string& caption) {
  return fmt::format("<figure><img src=\"{0}\" alt=\"{1}\"><figcaption>{1} "
                     "(<code>{0}</code>)</figcaption></figure>\n",
                     html_escape(file), html_escape(caption));
}

std::string figures_section(const calib::CalibrationOutcome& o, const CalibrationFigures& f) {
  if (!f.drawn) return "";
  std::string h = fmt::format(
      "<h2>Phase over the screen</h2>\n<p>Left: the decoded phase psi (lens periods, wrapped; "
      "a cyclic colour scale). Right: the residual psi_obs &minus; psi_model after the solve, "
      "wrapped to &plusmn;0.5 lens period, on one symmetric colour scale for all positions "
      "(&plusmn;{:.3f}); black points are outliers (|residual| &ge; {}), left out of the "
      "statistics. Structure in the residual means the model misses something there (glare, "
      "a reflection, a bezel, defocus).</p>\n",
      f.residual_scale_periods, kOutlierBoundPeriods);
  for (size_t i = 0; i < f.positions.size() && i < o.positions.size(); ++i) {
    const auto& pf = f.positions[i];
    const std::string& name = o.positions[i].name;
    h += fmt::format("<h3>{}</h3>\n", html_escape(name));
    if (pf.psi.empty()) {
      h += "<p>No phase samples kept for this position.</p>\n";
      continue;
    }
    h += "<div class=\"pair\">\n" + figure(pf.psi, name + ": decoded phase psi") +
         figure(pf.residual, name + ": phase residual") + "</div>\n";
  }
  if (!f.correction.empty())
    h += "<h2>Correction field</h2>\n<p>The estimated per-device correction w(u, v) of the lens "
         "phase, lens periods (zero mean and no linear trend: those are center, pitch and "
         "slope).</p>\n" +
         figure(f.correction, "correction field w(u, v)");
  if (!f.residual_histogram.empty())
    h += "<h2>Residuals</h2>\n" +
         figure(f.residual_histogram, "histogram of the phase residuals, all positions");
  return h;
}

std::string solver_section(const calib::CalibrationOutcome& o) {
  const auto& k = o.camera.camera_matrix;
  std::string h = fmt::format(
      "<h2>Camera and solver</h2>\n<p>Camera intrinsics ({}): {}x{} px, fx {:.1f}, fy {:.1f}, "
      "cx {:.1f}, cy {:.1f}.</p>\n<p>Solver {} in {:.2f} s; the whole calibration took {:.1f} "
      "s.</p>\n",
      o.camera_self_calibrated ? "self-calibrated from the board" : "given", o.camera.width,
      o.camera.height, k(0, 0), k(1, 1), k(0, 2), k(1, 2),
      o.solve.converged ? "converged" : "<b>did not converge</b>", o.solve.solve_seconds,
      o.seconds);
  if (!o.solve.report.empty())
    h += "<p>Stages (Ceres brief reports):</p>\n<pre>" + html_escape(o.solve.report) + "</pre>\n";
  return h;
}

std::string calibration_page(const ReferenceCalibration* reference,
                             const calib::CalibrationOutcome& o, const CalibrationFigures& f) {
  const auto& d = o.calibration.display;
  std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>lfd calibrate: "
                  "calibration report</title>\n" +
                  std::string(kStyle) + "</head><body>\n<h1>Calibration report</h1>\n";
  h += fmt::format("<p>Display <b>{}</b>: {}x{} panel at {:.1f} dpi ({:.1f} x {:.1f} cm); {} camera "
                   "position{}. Data: <a href=\"report.json\">report.json</a>.</p>\n",
                   d.serial.empty() ? std::string("(no serial)") : html_escape(d.serial),
                   d.screen_w, d.screen_h,
                   d.dpi, 100 * d.width_m(), 100 * d.height_m(), o.positions.size(),
                   o.positions.size() == 1 ? "" : "s");
  h += gates_section(o);
  h += warnings_section(o, !f.drawn && !figure_files(f).empty());
  h += colour_order_section(o);
  h += result_section(o);
  if (reference) h += reference_section(o.calibration, *reference);
  h += positions_section(o);
  h += figures_section(o, f);
  h += solver_section(o);
  return h + "</body></html>\n";
}

}  // namespace

std::filesystem::path write_calibration_report(const calib::CalibrationOutcome& outcome,
                                               const std::filesystem::path& dir,
                                               const ReferenceCalibration* reference) {
  std::filesystem::create_directories(dir);
  const CalibrationFigures figures = draw_calibration_figures(outcome, dir);
  nlohmann::ordered_json j = calib::outcome_report(outcome);
  j["figures"] = figures.drawn ? figure_files(figures) : std::vector<std::string>{};
  if (reference)
    j["reference"] = {{"name", reference->name},
                      {"calibration", display::to_json(reference->calibration)}};
  write_text_atomic(dir / "report.json", j.dump(2) + "\n");
  const auto index = dir / "index.html";
  write_text_atomic(index, calibration_page(reference, outcome, figures));
  return index;
}

}  // namespace lfd::report
