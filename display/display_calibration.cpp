#include "display/display_calibration.hpp"

#include <cmath>

#include "util/error.hpp"

namespace lfd::display {

namespace {

void require_finite(double value, const std::string& where, const char* field) {
  require_field(std::isfinite(value), where, field, "is not a finite number");
}

}  // namespace

void DisplayCalibration::check(const std::string& where) const {
  for (auto [value, field] : {std::pair{pitch_lpi, "pitch"}, {slope, "slope"},
                              {center_periods, "center"}, {view_cone_deg, "viewCone"},
                              {fringe, "fringe"}, {vertical_angle, "verticalAngle"},
                              {dpi, "DPI"}}) {
    require_finite(value, where, field);
  }
  require_field(pitch_lpi > 0, where, "pitch", "must be positive (lenticules per inch)");
  require_field(slope != 0, where, "slope", "must not be zero (lens slant run over rise)");
  require_field(dpi > 0, where, "DPI", "must be positive");
  require_field(screen_w > 0, where, "screenW", "must be a positive number of pixels");
  require_field(screen_h > 0, where, "screenH", "must be a positive number of pixels");
  require_field(view_cone_deg > 0 && view_cone_deg < 180, where, "viewCone",
                "must be between 0 and 180 degrees");
  require_field(cell_pattern_mode >= 0 && cell_pattern_mode <= 4, where, "CellPatternMode",
                "must be 0-4");
  require_field(subpixel_cells.size() <= 10, where, "subpixelCells",
                "has more than 10 cells (devices hold at most 10)");
  for (size_t i = 0; i < subpixel_cells.size(); ++i) {
    const auto& c = subpixel_cells[i];
    for (double v : {c.r_x, c.r_y, c.g_x, c.g_y, c.b_x, c.b_y})
      require_field(std::isfinite(v) && std::abs(v) <= 1.0, where,
                    "subpixelCells[" + std::to_string(i) + "]",
                    "offsets must be finite and within one pixel");
  }
}

}  // namespace lfd::display
