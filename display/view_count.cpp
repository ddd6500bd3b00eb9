#include "display/view_count.hpp"

#include "display/display_quilt.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

namespace lfd::display {

namespace {

// Quilt-friendly view counts (whole tile grids, as Looking Glass software uses).
constexpr std::array<int, 14> kViewCounts = {16, 24, 32, 40, 45, 48, 54, 60, 66, 72, 80, 88, 96, 100};

}  // namespace

ViewCountAdvice recommend_view_count(const Calibration& calibration) {
  const LensModel lens(calibration.display, calibration.correction);
  ViewCountAdvice a;
  // A subpixel covers 1/(subpixels per lens) of the phase: seen through the lens it emits a
  // box of that width in phase, blurred by the lens point spread sigma_A. Measured with
  // `lfd validate --sweep-views` (docs/display-model.md), the parallax blur a viewer sees is
  // within ~10 % of its floor (the lens blur) once the views are narrower than 1.6 sigma_eff:
  // more views only add crosstalk and render cost.
  const double subpixel_phase_width = 1.0 / lens.subpixels_per_lens();
  const double sigma_a = calibration.phase_blur_sigma.value_or(kDefaultPhaseBlurSigma);
  const double sigma_eff = std::sqrt(sigma_a * sigma_a + subpixel_phase_width *
                                                             subpixel_phase_width / 12.0);
  a.sampling_limit = lens.subpixels_per_lens() * std::max(1.0, std::abs(calibration.display.slope));
  a.blur_limit = 1.0 / (kViewWidthInSigmas * sigma_eff);
  // An error in the estimated phase (center and correction field uncertainty) shifts every
  // view; keep it under a quarter of a view. The residual RMS is not used: it is the noise of
  // single phase samples, which the fit averages away.
  double phase_variance = 0.0;
  for (const char* key : {"center_periods", "correction_rms_periods"})
    if (auto it = calibration.uncertainty.find(key); it != calibration.uncertainty.end())
      phase_variance += it->second * it->second;
  const double phase_error = std::sqrt(phase_variance);
  a.accuracy_limit = phase_error > 0 ? 1.0 / (4.0 * phase_error) : 1e9;

  const double limit = std::min({a.sampling_limit, a.blur_limit, a.accuracy_limit});
  a.views = kViewCounts.front();
  for (int views : kViewCounts)
    if (views <= limit + 1e-9) a.views = views;
  const QuiltGrid grid = quilt_grid_for_views(
      a.views, double(calibration.display.screen_w) / calibration.display.screen_h);
  a.cols = grid.cols;
  a.rows = grid.rows;
  a.rule = fmt::format(
      "views = largest quilt grid <= min(sampling {:.0f}, blur 1/(1.6*sigma_eff) = {:.1f}, "
      "accuracy 1/(4*phase uncertainty) = {}) with sigma_eff = sqrt(sigma_A^2 + w_sub^2/12) = "
      "{:.4f} periods (sigma_A {:.4f}{}, subpixel phase width w_sub {:.4f})",
      a.sampling_limit, a.blur_limit,
      a.accuracy_limit > 1e8 ? std::string("unlimited") : fmt::format("{:.1f}", a.accuracy_limit),
      sigma_eff, sigma_a, calibration.phase_blur_sigma ? " measured" : " default",
      subpixel_phase_width);
  return a;
}

}  // namespace lfd::display
