#include "display/display_figures.hpp"

#include <fmt/format.h>

namespace lfd::display {

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

}  // namespace lfd::display
