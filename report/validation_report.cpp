#include "report/validation_report.hpp"

#include <cmath>

#include <fmt/format.h>

#include "util/atomic_file.hpp"
#include "report/gnuplot.hpp"
#include "report/html.hpp"
#include "interlace/interlacer.hpp"

namespace lfd::report {

namespace {

// JSON has no infinity: a view that never lights (L_i - L_K <= 0) has no finite crosstalk.
nlohmann::ordered_json number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

std::string profiles_data(const validate::ViewProfiles& p) {
  std::string s = "# theta_deg L_0 .. L_{V-1} L_K\n";
  for (size_t k = 0; k < p.theta_deg.size(); ++k) {
    s += fmt::format("{:.5f}", p.theta_deg[k]);
    for (const auto& view : p.view) s += fmt::format(" {:.6g}", view[k]);
    s += fmt::format(" {:.6g}\n", p.black[k]);
  }
  return s;
}

std::string views_data(const validate::ViewSummary& s) {
  std::string out = "# view peak_theta_deg crosstalk adjacent_crosstalk separation\n";
  for (const auto& m : s.per_view)
    out += fmt::format("{} {:.5f} {:.6g} {:.6g} {:.6g}\n", m.view, m.peak_theta_deg,
                       std::isfinite(m.crosstalk) ? m.crosstalk : 1e9,
                       std::isfinite(m.adjacent_crosstalk) ? m.adjacent_crosstalk : 1e9,
                       m.separation);
  return out;
}

std::string plot_script(const ValidationCase& c, const std::string& stem) {
  const int v = c.profiles.views;
  std::string s;
  s += "set terminal pngcairo size 1100,520 font 'sans,11'\n";
  s += fmt::format("set output '{}_profiles.png.tmp'\n", stem);
  s += fmt::format("set title {}\n",
                   gnuplot_quote(fmt::format("Angular luminance of isolated views ({}): {} views, "
                                             "mean V = {:.3f}",
                                             c.name, v, c.summary.mean_separation)));
  s += "set xlabel 'viewing direction theta (degrees)'\nset ylabel 'luminance (white = 1)'\n";
  s += "set grid\nset key below\nset palette defined (0 '#3b4cc0', 0.5 '#bbbbbb', 1 '#b40426')\n";
  s += "unset colorbox\n";
  s += fmt::format(
      "plot for [i=2:{}] '{}_profiles.dat' using 1:i with lines lw 1.2 lc palette frac "
      "(i-2.0)/{} notitle, '{}_profiles.dat' using 1:{} with lines dt 2 lw 2 lc rgb 'black' "
      "title 'L_K (all black)'\n",
      v + 1, stem, std::max(1, v - 1), stem, v + 2);
  s += "set output\n";
  s += "set terminal pngcairo size 1100,620 font 'sans,11'\n";
  s += fmt::format("set output '{}_views.png.tmp'\n", stem);
  s += "set multiplot layout 2,1\nset style fill solid 0.7\nset boxwidth 0.8\nset grid ytics\n";
  s += "set lmargin at screen 0.08\nset rmargin at screen 0.80\n";
  s += fmt::format("set xrange [-0.7:{}]\n", v - 0.3);
  s += "set key outside right top vertical\nset xlabel ''\n";
  s += fmt::format("set title {}\n", gnuplot_quote(fmt::format(
                                         "View separation V_i at each view's peak ({})", c.name)));
  s += "set ylabel 'V_i'\nset yrange [0:1.05]\n";
  s += fmt::format("plot '{}_views.dat' using 1:5 with boxes lc rgb '#3b7dd8' title 'V_i'\n", stem);
  s += fmt::format("set title {}\n", gnuplot_quote(fmt::format(
                                         "Crosstalk X_i at each view's peak ({})", c.name)));
  s += "set ylabel 'X_i'\nset yrange [0:*]\nset xlabel 'view i'\nset boxwidth 0.4\n";
  s += "set key outside right top vertical\n";
  s += fmt::format(
      "plot '{0}_views.dat' using ($1-0.2):3 with boxes lc rgb '#d8703b' title 'all other views',"
      " '{0}_views.dat' using ($1+0.2):4 with boxes lc rgb '#6aa84f' title 'adjacent views'\n",
      stem);
  s += "unset multiplot\nset output\n";
  return s;
}

std::string html_page(const std::vector<ValidationCase>& cases, bool figures) {
  std::string h =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>lfd validate: view "
      "separation</title>\n<style>body{font-family:sans-serif;max-width:1150px;margin:2em auto;}"
      "table{border-collapse:collapse;}td,th{border:1px solid #ccc;padding:3px 8px;text-align:"
      "right;}img{max-width:100%;}</style></head><body>\n"
      "<h1>View separation</h1>\n<p>Angular luminance profiles L<sub>j</sub>(&theta;) of isolated "
      "views: for each view j the quilt with tile j white and the others black is interlaced with "
      "the <em>assumed</em> calibration and seen through the optics of the <em>true</em> "
      "calibration, averaged over the panel. At each view's peak &theta;<sub>i</sub>*: crosstalk "
      "X<sub>i</sub> = &Sigma;<sub>j&ne;i</sub>(L<sub>j</sub> &minus; L<sub>K</sub>) / "
      "(L<sub>i</sub> &minus; L<sub>K</sub>), view separation V<sub>i</sub> = (L<sub>i</sub> "
      "&minus; L<sub>K</sub>) / &Sigma;<sub>j</sub>(L<sub>j</sub> &minus; L<sub>K</sub>) "
      "(lfd's docs/validation.md). Data: <a href=\"validation.json\">validation.json</a>."
      "</p>\n<table><tr><th>case</th><th>true</th><th>assumed</th><th>views</th><th>view "
      "blend</th><th>panel points</th><th>psf &sigma;<sub>A</sub></th><th>mean V</th><th>min V</th><th>mean X</th>"
      "<th>mean X adjacent</th></tr>\n";
  for (const auto& c : cases)
    h += fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.4f}</td>"
        "<td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td></tr>\n",
        html_escape(c.name), html_escape(c.truth_source), html_escape(c.assumed_source),
        c.profiles.views,
        interlace::view_blend_name(c.profiles.blend),
        c.profiles.panel_points, c.profiles.psf_sigma_phase,
        c.summary.mean_separation, c.summary.min_separation, c.summary.mean_crosstalk,
        c.summary.mean_adjacent_crosstalk);
  h += "</table>\n";
  for (const auto& c : cases) {
    h += fmt::format("<h2>{}</h2>\n", html_escape(c.name));
    if (figures)
      h += fmt::format(
          "<img src=\"{0}_profiles.png\" alt=\"angular profiles\">\n<img src=\"{0}_views.png\" "
          "alt=\"per-view crosstalk and separation\">\n",
          html_escape(c.name));
    h += "<table><tr><th>view</th><th>peak &theta; (deg)</th><th>L<sub>i</sub> &minus; "
         "L<sub>K</sub></th><th>X<sub>i</sub></th><th>X<sub>i</sub> adjacent</th><th>V<sub>i"
         "</sub></th></tr>\n";
    for (const auto& m : c.summary.per_view)
      h += fmt::format(
          "<tr><td>{}</td><td>{:.2f}</td><td>{:.4f}</td><td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}"
          "</td></tr>\n",
          m.view, m.peak_theta_deg, m.peak_luminance, m.crosstalk, m.adjacent_crosstalk,
          m.separation);
    h += "</table>\n";
  }
  h += "</body></html>\n";
  return h;
}

}  // namespace

nlohmann::ordered_json to_json(const ValidationCase& c) {
  const auto& p = c.profiles;
  const auto& s = c.summary;
  nlohmann::ordered_json views = nlohmann::ordered_json::array();
  for (const auto& m : s.per_view)
    views.push_back({{"view", m.view},
                     {"peak_theta_deg", m.peak_theta_deg},
                     {"peak_luminance", m.peak_luminance},
                     {"crosstalk", number(m.crosstalk)},
                     {"adjacent_crosstalk", number(m.adjacent_crosstalk)},
                     {"separation", m.separation}});
  return {{"name", c.name},
          {"true_calibration", c.truth_source},
          {"assumed_calibration", c.assumed_source},
          {"views", p.views},
          {"blend", interlace::view_blend_name(p.blend)},
          {"distance_m", p.distance_m},
          {"eye_height_m",  // null: eyes level with each panel point
           p.eye_height_m ? nlohmann::ordered_json(*p.eye_height_m) : nlohmann::ordered_json()},
          {"psf_sigma_phase", p.psf_sigma_phase},
          {"panel_points", p.panel_points},
          {"mean_separation", s.mean_separation},
          {"min_separation", s.min_separation},
          {"mean_crosstalk", number(s.mean_crosstalk)},
          {"mean_adjacent_crosstalk", number(s.mean_adjacent_crosstalk)},
          {"per_view", views},
          {"profiles", {{"theta_deg", p.theta_deg}, {"views", p.view}, {"black", p.black}}}};
}

std::filesystem::path write_report(const std::filesystem::path& dir,
                                   const std::vector<ValidationCase>& cases) {
  std::filesystem::create_directories(dir);
  nlohmann::ordered_json j = {{"format", "lfd-validation"}, {"version", 1},
                              {"cases", nlohmann::ordered_json::array()}};
  std::string script;
  std::vector<std::string> figures;
  for (const auto& c : cases) {
    j["cases"].push_back(to_json(c));
    write_text_atomic(dir / (c.name + "_profiles.dat"), profiles_data(c.profiles));
    write_text_atomic(dir / (c.name + "_views.dat"), views_data(c.summary));
    script += plot_script(c, c.name);
    figures.push_back(c.name + "_profiles.png");
    figures.push_back(c.name + "_views.png");
  }
  write_text_atomic(dir / "validation.json", j.dump(2) + "\n");
  write_text_atomic(dir / "plots.gp", script);
  const bool drawn = run_gnuplot(dir, "plots.gp", figures);
  const auto index = dir / "index.html";
  write_text_atomic(index, html_page(cases, drawn));
  return index;
}

}  // namespace lfd::report
