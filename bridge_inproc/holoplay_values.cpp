#include "bridge_inproc/holoplay_values.hpp"

#include "display/lens_relations.hpp"

namespace lfd::bridge {

HoloPlayValues holoplay_values(const display::DisplayCalibration& c) {
  const display::ShaderTerms<double> terms = display::shader_terms(c.geometry(), c.pitch_lpi, c.slope);
  HoloPlayValues v;
  v.invview = c.inv_view ? 1 : 0;
  v.ri = c.flip_subp ? 2 : 0;
  v.bi = c.flip_subp ? 0 : 2;
  v.tilt = float(terms.tilt);
  v.displayaspect = float(double(c.screen_w) / c.screen_h);
  v.fringe = float(c.fringe);
  v.subp = float(1.0 / (3.0 * c.screen_w));
  v.pitch = float(terms.pitch_periods);
  v.center = float(c.center_periods);
  v.viewcone = float(c.view_cone_deg);
  return v;
}

}  // namespace lfd::bridge
