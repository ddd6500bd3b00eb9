#pragma once
// The lens of a panel nobody described, from photos of the probe gratings (sim/lens_probes.hpp;
// docs/calibration.md, "A panel nobody described"). Per probe the phasor
// sum_k I_k exp(2 pi i k / K) of every camera pixel is resampled onto the screen through the
// board's homography and Fourier transformed; the moire between grating and lens array is a
// peak at (Fu - P', Fv - P' tilt) (cycles per screen width, height), and a grating near
// 2 P' shows the lens one period in two, a peak at (Fu, Fv) - 2 (P', P' tilt). Every reading of
// every probe's strongest peaks is a hypothesis; the one whose predicted peaks in all probes
// are strongest wins (a harmonic or the camera's gamma explain fewer of them). The probes are
// drawn for RGB stripes; each colour channel is read on its own and the channels summed as
// RGB and as BGR stripes show them (on a BGR panel read as RGB, images of the grating a pixel
// lattice away are as strong as the grating itself): the better reading names the subpixel
// order. The three steps give the moire's sign, and with it the slant's. Accuracy: the seen view's own
// gradient over the screen (about a period) biases P' by that much, a few tenths of a percent,
// well inside what the described pipeline's coarse start takes (1 % pitch, 0.5 degree).
#include <string>
#include <vector>

#include "sim/capture_io.hpp"
#include "sim/patterns.hpp"

namespace lfd::calib {

struct ProbePeak {
  int probe = 0;
  double moire_u = 0, moire_v = 0;  // cycles per screen width, height
  double strength = 0;              // peak over the median of the probe's window
  double pitch_periods = 0;         // P' this peak implies (m = 1)
  double tilt_periods = 0;          // P' tilt it implies (lens periods over the height)
};

struct ProbeLensEstimate {
  std::string position;
  double pitch_periods = 0;  // lens periods per screen width (P')
  double tilt = 0;           // the lens model's tilt (lens_model.hpp)
  double pitch_lpi = 0, slope = 0, slant_deg = 0;  // visual.json terms
  bool bgr = false;    // the subpixel order whose reading explains the probes best
  double score = 0;    // how much of the probes' spectra the lens explains
  ProbePeak chosen;              // the winning lens's strongest peak
  std::vector<ProbePeak> peaks;  // every probe's strongest peak (lens fields unset)
};

struct ProbeMeasureOptions {
  double min_strength = 12;  // a peak weaker than this many times its window's median is noise
  int min_board_corners = 8;
};

// Measures the lens from the first position of `captures` (the coarse photos of an
// undescribed set). Throws InputError, naming the photo and what is missing: no board, the
// screen outside the photo, a probe photo of another pattern, no lens in the probes.
ProbeLensEstimate measure_lens_from_probes(const sim::PatternSet& set,
                                           const sim::PositionCaptures& captures,
                                           const ProbeMeasureOptions& options = {});

}  // namespace lfd::calib
