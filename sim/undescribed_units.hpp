#pragma once
// Panels nobody described, for the tests and `lfd bench calibration --undescribed` (docs/
// calibration.md, "A panel nobody described"): the truth of each is a lens no template holds,
// made a synthetic unit (synthetic_unit.hpp: a smooth warp, the cone 2 degrees wider) like
// the described families.
#include <string>
#include <vector>

#include "display/display_calibration.hpp"
#include "sim/patterns.hpp"

namespace lfd::sim {

struct UndescribedPanel {
  std::string label;
  display::DisplayCalibration display;  // the lens as built (before the synthetic warp)
};

// A 10.1" 1920x1200 tablet with a positive slant, a 15.6" 3840x2160 monitor with a BGR panel,
// a coarse 20 LPI sheet on a 13.3" 1920x1080 laptop screen; bare (no cover: a sheet or film
// laminated on the panel).
std::vector<UndescribedPanel> undescribed_panels();

// A small panel the test suite can afford: 640x400 at 100 DPI under a 35 LPI sheet slanted
// +11 degrees, BGR.
UndescribedPanel small_undescribed_panel();
// Its coarse set as the tests photograph it with a 640-px camera (the screen spans ~340 px of
// it): 4 board squares on the short side (as `lfd patterns --screen` draws them) and a
// narrower pitch range (20-60 LPI) than the default, which keeps the photos few.
PatternSet small_undescribed_probes();

}  // namespace lfd::sim
