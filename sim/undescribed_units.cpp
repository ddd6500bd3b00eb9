#include "sim/undescribed_units.hpp"

#include <cmath>

#include "display/lens_relations.hpp"

namespace lfd::sim {

namespace {

UndescribedPanel panel(std::string label, int w, int h, double diagonal_in, double lpi,
                       double slant_deg, double cone_deg, bool bgr) {
  UndescribedPanel p;
  p.label = std::move(label);
  display::DisplayCalibration& d = p.display;
  d.serial = "undescribed";
  d.screen_w = w;
  d.screen_h = h;
  d.dpi = std::hypot(w, h) / diagonal_in;
  d.pitch_lpi = lpi;
  d.slope = display::slope_of_slant_deg(slant_deg);
  d.center_periods = 0.37;
  d.view_cone_deg = cone_deg;
  d.inv_view = true;
  d.flip_subp = bgr;
  d.check(p.label);
  return p;
}

}  // namespace

std::vector<UndescribedPanel> undescribed_panels() {
  return {panel("10\" tablet", 1920, 1200, 10.1, 43.7, 9.46, 33.0, false),
          panel("15.6\" 4K BGR", 3840, 2160, 15.6, 61.3, -12.53, 28.0, true),
          panel("20 LPI sheet", 1920, 1080, 13.3, 20.0, -5.71, 24.0, false)};
}

UndescribedPanel small_undescribed_panel() {
  UndescribedPanel p = panel("small 35 LPI", 640, 400, std::hypot(640, 400) / 100.0, 35.0,
                             11.0, 30.0, true);
  return p;
}

PatternSet small_undescribed_probes() {
  const display::DisplayCalibration d = small_undescribed_panel().display;
  PatternOptions options;
  options.board_squares_short = 4;
  ProbeOptions probes;
  probes.min_lpi = 20;
  probes.max_lpi = 60;
  probes.camera_px_across = 340;
  return plan_undescribed_patterns(d.screen_w, d.screen_h, d.dpi, options, probes);
}

}  // namespace lfd::sim
