#pragma once
// Exposure that drifts between the photos of one phase-shifted series (webcams that do not
// hold exposure, backlight flicker, auto gain): photo k is g_k I_k + o_k. A drift's first
// harmonic over the steps, sum_k g_k exp(2 pi i k/K), leaks the mean level a into the phasor
// and biases the phase by about |g_1| a / b; the phase images alone cannot tell it from a
// phase change (it is one more cosine in k per block). What can: the blocks that show no
// fringe at all (the bezel, the room, the corner markers' white and black), where every step
// should read the same. Their levels fit g_k and o_k per photo (gain and offset against the
// series' mean level), and the block sums are corrected before the phase is taken.
#include <vector>

#include "calib/block_phasors.hpp"

namespace lfd::calib {

struct PhotoExposure {
  double gain = 1, offset = 0;  // this photo = gain * (the series' mean photo) + offset
};

struct ExposureDrift {
  std::vector<PhotoExposure> photos;  // one per capture of the series; empty: not estimated
  int reference_blocks = 0;           // unmodulated blocks the fit used
  bool offset_fitted = false;         // their levels spread enough to fit an offset too
  double max_gain_change() const;     // max |gain - 1|
};

struct ExposureDriftOptions {
  int min_reference_blocks = 20;
  // A block is a reference when no step's level strays from its mean by more than this
  // fraction (after a first correction with a 3x looser bound, since the drift itself moves
  // the levels). Its levels, not its phasor: a block whose steps are out of order can have a
  // small phasor and still change from step to step.
  double max_reference_spread = 0.03;
};

// Empty `photos` when too few unmodulated blocks were seen (nothing to correct with).
ExposureDrift estimate_exposure_drift(const BlockPhasors& phasors,
                                      const ExposureDriftOptions& options = {});
// Divides the drift out of the block levels and rebuilds the phasor sums from them.
void remove_exposure_drift(BlockPhasors& phasors, const ExposureDrift& drift);

}  // namespace lfd::calib
