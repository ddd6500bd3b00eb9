#pragma once
// The lens parameters of one display unit, as Looking Glass stores them in visual.json
// (docs/file-formats.md "visual.json"). Units follow Looking Glass: pitch in lenticules per
// inch, slope as "run over rise", center in lens periods, viewCone in degrees.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "display/lens_relations.hpp"
#include "util/default_display.hpp"

namespace lfd::display {

// Physical emitter position of each colour relative to its pixel centre, in pixel units
// (Gen3 panels; x right, y up).
struct SubpixelCell {
  double r_x = 0, r_y = 0, g_x = 0, g_y = 0, b_x = 0, b_y = 0;
};

struct DisplayCalibration {
  std::string serial;
  std::string config_version = "3.0";
  double pitch_lpi = 50.0;
  double slope = -7.0;
  double center_periods = 0.0;
  double view_cone_deg = kDefaultViewConeDeg;
  double fringe = 0.0;
  double vertical_angle = 0.0;
  bool inv_view = true;
  double dpi = 283.0;
  int screen_w = 3840;
  int screen_h = 2160;
  bool flip_image_x = false;
  bool flip_image_y = false;
  bool flip_subp = false;
  int cell_pattern_mode = 0;
  std::vector<SubpixelCell> subpixel_cells;
  // The acrylic block or cover glass in front of the lens array (lens_relations.hpp). Not a
  // visual.json field: calibration.json's "cover" holds it; a plain visual.json reads as a bare
  // panel, and cover_layer_for_family() (cover_layer.hpp) gives a unit family's default.
  CoverLayer cover;

  // The object as read, with every field this struct does not model (and the original
  // spelling and number formatting of those it does), so a round trip loses nothing.
  nlohmann::ordered_json source = nlohmann::ordered_json::object();

  double pixel_pitch_m() const { return 0.0254 / dpi; }
  double width_m() const { return screen_w * pixel_pitch_m(); }
  double height_m() const { return screen_h * pixel_pitch_m(); }
  bool has_cells() const { return !subpixel_cells.empty(); }
  // What the shader terms need of the screen (lens_relations.hpp).
  ScreenGeometry geometry() const {
    return {double(screen_w), double(screen_h), dpi, flip_image_x};
  }

  // Throws lfd::InputError("<where>: <field>: <problem>") for values no display can have:
  // non-positive pitch/DPI/size, zero or non-finite slope, NaN anywhere, CellPatternMode
  // outside 0-4, more than 10 cells.
  void check(const std::string& where) const;
};

}  // namespace lfd::display
