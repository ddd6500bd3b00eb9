#pragma once
// How many views a display can show (docs/display-model.md "Recommended view count"). The
// calibration drives it: views narrower than what the lens can separate only add crosstalk and
// rendering cost.
#include <string>

#include "display/calibration_file.hpp"
#include "display/lens_model.hpp"
#include "util/default_display.hpp"

namespace lfd::display {

struct ViewCountAdvice {
  int views = kDefaultViewCount;
  int cols = 5;
  int rows = 9;
  double sampling_limit = 0;   // distinct subpixel phases per lens period
  double blur_limit = 0;       // 1 / (1.6 sigma_eff): views as narrow as the optics resolves
  double accuracy_limit = 0;   // 1 / (4 x phase uncertainty): correction/phase error < 1/4 view
  std::string rule;            // the rule in words with the numbers, for `lfd info`
};

// Default lens point spread in lens periods when a calibration has not measured it.
inline constexpr double kDefaultPhaseBlurSigma = 0.008;
// The narrowest useful view, in units of the combined phase spread sigma_eff (measured with
// `lfd validate --sweep-views`: parallax blur within ~10 % of its floor).
inline constexpr double kViewWidthInSigmas = 1.6;

ViewCountAdvice recommend_view_count(const Calibration& calibration);

}  // namespace lfd::display
