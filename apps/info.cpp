// lfd info: the figures a person wants to know about a display's calibration.
#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "display/calibration_file.hpp"
#include "display/lens_model.hpp"
#include "display/view_count.hpp"

namespace lfd::apps {

namespace {

// What `lfd info` shows, derived once from the calibration for both outputs.
struct DisplayFigures {
  const display::Calibration& cal;
  const std::string& path;
  const display::DisplayCalibration& d = cal.display;
  const display::LensModel lens{d, cal.correction};
  const display::ViewCountAdvice views = display::recommend_view_count(cal);
  const double width_mm = d.width_m() * 1000, height_mm = d.height_m() * 1000;
  const double diagonal_in = std::hypot(d.width_m(), d.height_m()) / 0.0254;
  const double lens_period_mm = 25.4 / d.pitch_lpi;
  const std::array<double, 2> range = cal.correction.range();
};

// The figures as JSON (--json), also the source of the printed subpixel layout.
nlohmann::ordered_json figures_json(const DisplayFigures& f) {
  const auto& [cal, path, d, lens, views, width_mm, height_mm, diagonal_in, lens_period_mm, range] = f;
  nlohmann::ordered_json j;
  j["file"] = path;
  j["serial"] = d.serial;
  j["panel"] = {{"width_px", d.screen_w}, {"height_px", d.screen_h}, {"dpi", d.dpi},
                {"width_mm", width_mm}, {"height_mm", height_mm}, {"diagonal_in", diagonal_in}};
  j["lens"] = {{"pitch_lpi", d.pitch_lpi},
               {"lens_period_mm", lens_period_mm},
               {"lenses_across_screen", lens.pitch_periods()},
               {"pixels_per_lens", d.screen_w / lens.pitch_periods()},
               {"subpixels_per_lens", lens.subpixels_per_lens()},
               {"slope", d.slope},
               {"slant_deg", lens.slant_deg()},
               {"tilt", lens.tilt()},
               {"center_periods", d.center_periods},
               {"inv_view", d.inv_view},
               {"subpixel_layout", d.has_cells() ? fmt::format("Gen3 cells (mode {}, {} cells)",
                                                               d.cell_pattern_mode,
                                                               d.subpixel_cells.size())
                                                 : (d.flip_subp ? "BGR stripes" : "RGB stripes")}};
  j["view_cone_deg"] = d.view_cone_deg;
  if (cal.view_cone_measured_deg) j["view_cone_measured_deg"] = *cal.view_cone_measured_deg;
  if (cal.view_cone_nominal_deg) j["view_cone_nominal_deg"] = *cal.view_cone_nominal_deg;
  if (!cal.correction.empty())
    j["correction"] = {{"grid", fmt::format("{}x{}", cal.correction.nx(), cal.correction.ny())},
                       {"min_periods", range[0]}, {"max_periods", range[1]}};
  j["recommended_views"] = {{"views", views.views}, {"cols", views.cols}, {"rows", views.rows},
                            {"rule", views.rule}};
  return j;
}

// The figures for a person, one per line.
void print_figures(const DisplayFigures& f, const nlohmann::ordered_json& j) {
  const auto& [cal, path, d, lens, views, width_mm, height_mm, diagonal_in, lens_period_mm, range] = f;
  fmt::print("{}{}\n", path, d.serial.empty() ? "" : "  (serial " + d.serial + ")");
  fmt::print("  panel            {} x {} px, {} DPI, {:.1f} x {:.1f} mm ({:.1f}\" diagonal)\n",
             d.screen_w, d.screen_h, d.dpi, width_mm, height_mm, diagonal_in);
  fmt::print("  lens pitch       {:.6f} lenticules/inch ({:.4f} mm period)\n", d.pitch_lpi,
             lens_period_mm);
  fmt::print("  lenses across    {:.4f} (horizontally, over the screen width)\n",
             lens.pitch_periods());
  fmt::print("  per lens         {:.3f} pixels = {:.3f} subpixels along a row\n",
             d.screen_w / lens.pitch_periods(), lens.subpixels_per_lens());
  fmt::print("  slant            {:.5f} deg from vertical (slope {})\n", lens.slant_deg(), d.slope);
  fmt::print("  center           {:.6f} lens periods{}\n", d.center_periods,
             d.inv_view ? ", views inverted (invView)" : "");
  fmt::print("  subpixels        {}\n", j["lens"]["subpixel_layout"].get<std::string>());
  // The measured cone is the cone (display.viewCone holds it); the nominal is provenance.
  fmt::print("  view cone        {} deg{}\n", d.view_cone_deg,
             cal.view_cone_measured_deg
                 ? (cal.view_cone_nominal_deg
                        ? fmt::format(" (measured; nominal {:.2f})", *cal.view_cone_nominal_deg)
                        : std::string(" (measured)"))
                 : std::string(""));
  if (!cal.correction.empty())
    fmt::print("  correction       {}x{} B-spline, {:.4f} .. {:.4f} lens periods\n",
               cal.correction.nx(), cal.correction.ny(), range[0], range[1]);
  fmt::print("  recommended      {} views ({} x {} quilt)\n", views.views, views.cols, views.rows);
  fmt::print("  rule             {}\n", views.rule);
}

}  // namespace

int RunInfo(int argc, char** argv) {
  CLI::App app{"Print the figures derived from a calibration: lenses across the screen, "
               "subpixels per lens, slant, view cone, recommended view count and its rule.\n"
               "\nExamples:\n"
               "  lfd info --calibration visual.json\n"
               "  lfd info --calibration calibration.json --json\n"
               "  lfd info --device auto",
               "info"};
  DisplaySource source;
  bool json = false;
  source.add(app, "--calibration", "calibration.json or visual.json");
  app.add_flag("--json", json, "machine-readable output");
  if (auto code = parse(app, argc, argv)) return *code;

  const display::Calibration cal = source.load();
  const DisplayFigures figures{.cal = cal, .path = source.name()};
  const nlohmann::ordered_json j = figures_json(figures);
  if (json) {
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  print_figures(figures, j);
  return 0;
}

}  // namespace lfd::apps
