#pragma once
// The cover layer a Looking Glass unit family has in front of its lens array, by default.
// visual.json holds no such field, so a plain visual.json reads as a bare panel; the calibration
// pipeline starts from the family's value, and calibration.json's "cover" records what was used
// (docs/display-model.md, "The cover layer").
#include <string>

#include "display/display_calibration.hpp"

namespace lfd::display {

struct CoverDefault {
  CoverLayer cover;     // thickness 0: a bare panel (unknown family)
  std::string family;   // "Portrait", "Gen1 8.9\"", ... or "unknown"
  // How far off the estimate may be, 1 sigma (the calibration's prior on the thickness,
  // docs/calibration.md "The cover layer"); 0 for an unknown family.
  double thickness_sigma_m = 0;
};

// By the serial's family prefix (LKG-2K, LKG-4K, LKG-PORT, LKG-A, LKG-B, LKG-H, LKG-J, LKG-E),
// else by the panel (resolution and DPI) of a known family, else a bare panel.
CoverDefault cover_layer_for_family(const DisplayCalibration& display);

}  // namespace lfd::display
