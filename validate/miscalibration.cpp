#include "validate/miscalibration.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

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

calib::Calibration apply(const calib::Calibration& calibration, const Miscalibration& e) {
  calib::Calibration c = calibration;
  // The slant is the lens angle from vertical, atan(1/slope); perturb the angle, not the slope.
  const double slant = std::atan(1.0 / c.display.slope) + e.slant_deg * std::numbers::pi / 180.0;
  c.display.slope = 1.0 / std::tan(slant);
  c.display.pitch_lpi *= 1.0 + e.pitch_relative;
  c.display.center_periods += e.center_periods;
  if (e.drop_correction) c.correction = calib::CorrectionField();
  return c;
}

}  // namespace lfd::validate
