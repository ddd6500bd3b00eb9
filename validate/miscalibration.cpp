#include "validate/miscalibration.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "display/lens_relations.hpp"

namespace lfd::validate {

std::string Miscalibration::describe() const {
  std::string s;
  auto add = [&](const std::string& part) { s += (s.empty() ? "" : ", ") + part; };
  if (slant_deg != 0) add(fmt::format("slant {:+g} deg", slant_deg));
  if (pitch_relative != 0) add(fmt::format("pitch {:+g} relative", pitch_relative));
  if (center_periods != 0) add(fmt::format("center {:+g} periods", center_periods));
  if (drop_correction) add("no correction field");
  return s.empty() ? "none" : s;
}

display::Calibration apply(const display::Calibration& calibration, const Miscalibration& e) {
  display::Calibration c = calibration;
  // The slant is the lens angle from vertical, atan(1/slope); perturb the angle, not the slope.
  c.display.slope = display::slope_of_slant_deg(display::slant_deg_of_slope(c.display.slope) + e.slant_deg);
  c.display.pitch_lpi *= 1.0 + e.pitch_relative;
  c.display.center_periods += e.center_periods;
  if (e.drop_correction) c.correction = display::CorrectionField();
  return c;
}

}  // namespace lfd::validate
