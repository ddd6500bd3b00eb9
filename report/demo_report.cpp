#include "report/demo_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "util/atomic_file.hpp"
#include "report/html.hpp"

namespace lfd::report {

std::filesystem::path write_demo_report(const std::filesystem::path& dir, const DemoReport& r) {
  nlohmann::ordered_json j;
  j["unit"] = r.unit_source;
  j["scene"] = r.scene_source;
  j["scene_gaussians"] = r.scene_gaussians;
  j["views"] = r.views;
  j["view_count_rule"] = r.view_rule;
  if (!r.calibration_note.empty()) j["calibration"] = r.calibration_note;
  for (const auto& c : r.captures)
    j["captures"].push_back({{"position", c.name}, {"angle_deg", c.angle_deg},
                             {"expected_view", c.expected_view}, {"scene", c.scene_image},
                             {"numbered", c.numbered_image}});
  for (const auto& v : r.validation)
    j["validation"].push_back({{"configuration", v.configuration},
                               {"mean_view_separation", v.mean_separation},
                               {"mean_crosstalk", v.mean_crosstalk}});
  write_text_atomic(dir / "report.json", j.dump(2) + "\n");

  std::string html = fmt::format(R"(<!doctype html>
<html><head><meta charset="utf-8"><title>lfd demo</title>
<style>body{{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}}
img{{max-width:100%;border:1px solid #ccc}} table{{border-collapse:collapse}}
td,th{{border:1px solid #ccc;padding:4px 10px;text-align:right}} .grid{{display:grid;grid-template-columns:repeat(3,1fr);gap:8px}}
figcaption{{font-size:90%;color:#555}}</style></head><body>
<h1>lfd demo</h1>
<p>A simulated display unit: <code>{}</code> (a real unit's factory calibration) with a smooth
lens-array warp that only its own calibration describes, calibrated from simulated photographs.
{} views ({}).</p>
<p>Scene: <code>{}</code>, {} Gaussians, rendered with G2LF (64 sweeping planes, P<sub>s</sub> = 2, bilinear).</p>
)",
                                 html_escape(r.unit_source), r.views, html_escape(r.view_rule),
                                 html_escape(r.scene_source), r.scene_gaussians);
  if (!r.calibration_note.empty()) html += "<h2>Calibration</h2><p>" + html_escape(r.calibration_note) + "</p>\n";
  html += "<h2>Photographs of the display</h2>\n<div class=\"grid\">\n";
  for (const auto& c : r.captures)
    html += fmt::format("<figure><img src=\"{}\"><figcaption>{} ({:+.1f} deg)</figcaption></figure>\n",
                        c.scene_image, c.name, c.angle_deg);
  for (const auto& c : r.captures)
    html += fmt::format(
        "<figure><img src=\"{}\"><figcaption>numbered quilt from the {}: should read view {}</figcaption></figure>\n",
        c.numbered_image, c.name, c.expected_view);
  html += "</div>\n<h2>View separation</h2>\n<table><tr><th>display driven with</th>"
          "<th>mean view separation V</th><th>mean crosstalk X</th></tr>\n";
  for (const auto& v : r.validation)
    html += fmt::format("<tr><td style=\"text-align:left\">{}</td><td>{:.1f} %</td><td>{:.2f}</td></tr>\n",
                        html_escape(v.configuration), 100.0 * v.mean_separation, v.mean_crosstalk);
  html += "</table>\n<p>Angular profiles and per-view figures: <a href=\"validation/index.html\">"
          "validation report</a>.</p>\n<h2>Quilts and panels</h2>\n<div class=\"grid\">\n";
  for (const auto& [img, caption] :
       std::vector<std::pair<std::string, std::string>>{{"scene_panel.png", "interlaced scene panel"},
                                                        {"numbered_panel.png", "interlaced numbered panel"}})
    html += fmt::format("<figure><img src=\"{}\"><figcaption>{}</figcaption></figure>\n", img, caption);
  html += "</div>\n</body></html>\n";
  write_text_atomic(dir / "index.html", html);
  return dir / "index.html";
}

}  // namespace lfd::report
