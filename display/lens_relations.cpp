#include "display/lens_relations.hpp"

namespace lfd::display {

PitchSlope pitch_slope_from_shader_terms(const ScreenGeometry& g, double pitch_periods,
                                         double tilt) {
  const double slope = g.height_px / (g.width_px * tilt) * (g.flip_image_x ? -1.0 : 1.0);
  const double pitch_lpi = pitch_periods / ((g.width_px / g.dpi) * std::cos(std::atan(1.0 / slope)));
  return {pitch_lpi, slope};
}

double view_cone_from_fraction_per_tan(double k) {
  return 2.0 * std::atan(0.5 / k) * 180.0 / std::numbers::pi;
}

}  // namespace lfd::display
