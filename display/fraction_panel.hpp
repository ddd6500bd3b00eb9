#pragma once
// A panel that encodes each subpixel's own view fraction f as 1/2 + 1/2 cos(2 pi f) (or sin):
// what an eye or a camera sees of the cos and sin panels, less half of white, is the phasor of
// the view fraction it sees, whatever the lens blur does to the amplitude and across the wrap.
// Validation measures the seen view with it; the simulator's tests check the optics with it.
#include "display/lens_model.hpp"
#include "util/image.hpp"

namespace lfd::display {

// screenW x screenH, 3 channels, values in [0, 1].
ImageF view_fraction_panel(const LensModel& lens, bool sine);

}  // namespace lfd::display
