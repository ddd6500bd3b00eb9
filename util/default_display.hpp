#pragma once
// The display lfd assumes where nothing says otherwise: a Looking Glass's nominal 40-degree
// horizontal view cone and 45 views (a 5x9 quilt) (docs/display-model.md, "The quilt for a
// display"). Here, below everything, because the display model (display/) and the quilt
// geometry of render, which may not include each other, both start from them.
#include <numbers>

namespace lfd {

inline constexpr double kDefaultViewConeDeg = 40.0;
inline constexpr int kDefaultViewCount = 45;

// The default cone in radians, as the renderers' float geometry holds it.
inline constexpr float kDefaultViewConeRad = float(kDefaultViewConeDeg * std::numbers::pi / 180.0);

}  // namespace lfd
