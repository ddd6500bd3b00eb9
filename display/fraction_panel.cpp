#include "display/fraction_panel.hpp"

#include <cmath>
#include <numbers>

namespace lfd::display {

ImageF view_fraction_panel(const LensModel& lens, bool sine) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const auto& c = lens.calibration();
  ImageF panel(c.screen_w, c.screen_h, 3);
  for (int row = 0; row < c.screen_h; ++row)
    for (int x = 0; x < c.screen_w; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        const double a = kTwoPi * lens.subpixel_view_fraction(x, row, ch);
        panel.at(x, row, ch) = float(0.5 + 0.5 * (sine ? std::sin(a) : std::cos(a)));
      }
  return panel;
}

}  // namespace lfd::display
