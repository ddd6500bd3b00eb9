// lfd info: the figures a person wants to know about a display's calibration.
#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "display/calibration_file.hpp"
#include "display/display_figures.hpp"

namespace lfd::apps {

namespace {

// The figures for a person, one per line.
void print_figures(const display::DisplayFigures& f, const nlohmann::ordered_json& j) {
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
  const display::DisplayFigures figures{.cal = cal, .path = source.name()};
  const nlohmann::ordered_json j = display::figures_json(figures);
  if (json) {
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  print_figures(figures, j);
  return 0;
}

}  // namespace lfd::apps
