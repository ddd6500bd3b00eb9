#pragma once
// Phase decoding (docs/calibration.md section 3.2). The K captures of the phase-shifted patterns
// give, per camera pixel and channel, I_k = a + b cos(2 pi (psi - k/K)); so
//   sum_k I_k exp(2 pi i k / K) = (K/2) b exp(2 pi i psi)
// and psi, the nominal view fraction of the subpixels the camera sees, is its argument. The
// phasors of the three channels and of a block of camera pixels are summed before the
// argument is taken: the channels see the same psi (each subpixel's true and nominal phases
// are taken at its own physical position), and the block sum averages the lens-scale moire
// and the sensor noise without biasing the phase.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "calib/decoding/channel_phase.hpp"
#include "calib/phasors/exposure_drift.hpp"
#include "sim/patterns.hpp"
#include "calib/registration/registration.hpp"

namespace lfd::calib {

struct PhaseSample {
  float u = 0, v = 0;  // panel point the camera looks at (registration)
  float psi = 0;       // decoded wrapped phase in [0, 1)
  float modulation = 0;
};

struct PhaseDecodeOptions {
  int block_px = 4;              // camera pixels per block side
  double min_modulation = 0.08;  // b / a below this: no usable phase (bezel, glare, defocus)
  double panel_margin = 0.01;    // of the panel size, skipped along the edges
  // Divide out each photo's gain and offset, measured where nothing is modulated
  // (calib/phasors/exposure_drift.hpp): webcams that do not hold exposure, backlight flicker.
  bool correct_exposure_drift = true;
  // ... with a gain that varies along the rows (rolling-shutter flicker banding); off, one
  // gain per photo (a diagnostic: what the row fit is worth).
  bool exposure_row_gain = true;
};

struct DecodedPhase {
  std::vector<PhaseSample> samples;
  // Parallel to samples: each colour channel's own phase against psi (channel_phase.hpp),
  // for the colour-order check (colour_order.hpp).
  std::vector<ChannelPhase> channels;
  long blocks_on_panel = 0;    // blocks whose centre maps inside the usable panel
  long blocks_clipped = 0;     // ... of which saturated in some capture
  long blocks_low_modulation = 0;
  double median_modulation = 0;
  // Per capture: correlation of (I_k - a) with cos(2 pi (psi - k/K)); near 1 for the right
  // pattern, low for a capture of some other pattern.
  std::vector<double> step_correlation;
  ExposureDrift exposure;  // what was divided out (empty photos: nothing)
};

// `captures[k]` is the capture of phase step k: CV_32FC3, linear-ish values in [0, 1].
DecodedPhase decode_phase(const std::vector<cv::Mat>& captures, const Registration& registration,
                          const sim::PatternSet& set, const PhaseDecodeOptions& options = {});

}  // namespace lfd::calib
