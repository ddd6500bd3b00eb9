#pragma once
// How many views a display can show (DESIGN section 6). The calibration drives it: views
// narrower than what the lens can separate only add crosstalk and rendering cost.
#include <string>

#include "calib/calibration_file.hpp"
#include "calib/lens_model.hpp"

namespace lfd::calib {

struct ViewCountAdvice {
  int views = 45;
  int cols = 5;
  int rows = 9;
  double sampling_limit = 0;   // distinct subpixel phases per lens period
  double blur_limit = 0;       // 1 / (2.5 sigma_A): views at least as wide as the lens PSF core
  double accuracy_limit = 0;   // 1 / (4 x phase uncertainty): correction/phase error < 1/4 view
  std::string rule;            // the rule in words with the numbers, for `lfd info`
};

// Default lens point spread in lens periods when a calibration has not measured it.
inline constexpr double kDefaultPhaseBlurSigma = 0.008;

ViewCountAdvice recommend_view_count(const Calibration& calibration);

}  // namespace lfd::calib
