#pragma once
// What a miscalibration costs: a calibration with its lens parameters perturbed by known
// amounts, to drive the interlacer with while the optics follow the truth.
#include <string>

#include "display/calibration_file.hpp"

namespace lfd::validate {

struct Miscalibration {
  double slant_deg = 0;         // added to the lens slant atan(1/slope)
  double pitch_relative = 0;    // pitch *= 1 + pitch_relative
  double center_periods = 0;    // added to center
  bool drop_correction = false; // forget the correction field (what a plain visual.json does)

  bool empty() const {
    return slant_deg == 0 && pitch_relative == 0 && center_periods == 0 && !drop_correction;
  }
  std::string describe() const;  // e.g. "slant +0.01 deg, pitch +2e-05"
};

display::Calibration apply(const display::Calibration& calibration, const Miscalibration& error);

}  // namespace lfd::validate
