#include "validate/seen_down_the_screen.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include "display/fraction_panel.hpp"
#include "display/lens_relations.hpp"
#include "display/view_count.hpp"
#include "sim/simulator.hpp"
#include "util/error.hpp"

namespace lfd::validate {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double fraction_of(std::complex<double> z) {
  return display::wrap_fraction(std::arg(z) / kTwoPi);
}

}  // namespace

double fraction_difference(double a, double b) {
  const double d = a - b;
  return d - std::floor(d + 0.5);
}

std::vector<HeightSample> seen_down_the_screen(const display::Calibration& truth,
                                               const Eigen::Vector3d& eye_m, int rows,
                                               double region_fraction) {
  if (!(eye_m.z() > 0)) throw_input_error("eye: z = {} m; the eye must be in front of the panel", eye_m.z());
  if (rows < 2) throw_input_error("rows: {} (expected at least 2)", rows);
  if (!(region_fraction > 0 && region_fraction <= 1))
    throw_input_error("region: {} (expected a fraction in (0, 1])", region_fraction);
  const auto& d = truth.display;
  const display::LensModel lens(d, truth.correction);
  const sim::DisplaySimulator simulator{lens};
  const ImageF cos_panel = display::view_fraction_panel(lens, false);
  const ImageF sin_panel = display::view_fraction_panel(lens, true);
  const ImageF white(d.screen_w, d.screen_h, 3, 1.0f);
  const double psf = truth.phase_blur_sigma.value_or(display::kDefaultPhaseBlurSigma);
  // Samples across four lens periods and nine pixel rows, 9/8 of a row apart: every position
  // within a lens and within a row counts alike. Both matter: a subpixel's fraction is that of
  // its centre, while the slanted lens sees it at other phases above and below the centre
  // (tilt pitch' / H, 0.02 period a row), and the slant shifts the subpixel grid under the lens
  // from row to row, so the subpixels' discrete fractions average out.
  const double lens_m = d.width_m() / lens.pitch_periods();
  const double row_m = d.height_m() / d.screen_h;
  constexpr int kAcross = 32, kRows = 8;

  std::vector<HeightSample> out(static_cast<size_t>(rows));
#pragma omp parallel for schedule(dynamic, 1)
  for (int j = 0; j < rows; ++j) {
    const double y = (double(j) / (rows - 1) - 0.5) * region_fraction * d.height_m();
    std::complex<double> seen = 0, predicted = 0;
    for (int k = 0; k < kAcross * kRows; ++k) {
      const int i = k % kAcross, r = k / kAcross;
      const Eigen::Vector3d p(eye_m.x() + ((i + 0.5) / kAcross - 0.5) * 4.0 * lens_m,
                              y + (r - 0.5 * (kRows - 1)) * 1.125 * row_m, 0.0);
      const auto c = simulator.radiance(cos_panel, p, eye_m, psf);
      const auto s = simulator.radiance(sin_panel, p, eye_m, psf);
      const auto w = simulator.radiance(white, p, eye_m, psf);
      for (int ch = 0; ch < 3; ++ch) seen += std::complex<double>(c[ch] - 0.5 * w[ch], s[ch] - 0.5 * w[ch]);
      const Eigen::Vector3d to_eye = eye_m - p;
      const double f = display::seen_fraction_through_cover(to_eye.x(), to_eye.y(), to_eye.z(),
                                                          d.cover, lens.line_tilt(),
                                                          d.view_cone_deg);
      predicted += std::polar(1.0, kTwoPi * f);
    }
    out[size_t(j)] = {y, fraction_of(seen), fraction_of(predicted)};
  }
  return out;
}

}  // namespace lfd::validate
