#pragma once
// Exposure that drifts between the photos of one phase-shifted series (webcams that do not
// hold exposure, backlight flicker, auto gain): photo k is g_k I_k + o_k. A drift's first
// harmonic over the steps, sum_k g_k exp(2 pi i k/K), leaks the mean level a into the phasor
// and biases the phase by about |g_1| a / b; the phase images alone cannot tell it from a
// phase change (it is one more cosine in k per block). What can: the blocks that show no
// fringe at all (the bezel, the room, the corner markers' white and black), where every step
// should read the same. Their levels fit g_k and o_k per photo (gain and offset against the
// series' mean level), and the block sums are corrected before the phase is taken.
//
// A rolling shutter under flickering room light exposes the rows at different
// moments of the flicker: the gain bands along the image rows, g_k(y), with a phase of its own
// in every photo. So the gain is a smooth function of the row (a uniform cubic B-spline over
// the image height), fitted from the references of every row (the bezel and room left and
// right of the screen); one gain per photo where the references do not cover every part of
// the height.
#include <vector>

#include "calib/phasors/block_phasors.hpp"

namespace lfd::calib {

struct PhotoExposure {
  // This photo = gain * (the series' mean photo) + offset; `gain` is the mean over the rows.
  double gain = 1, offset = 0;
  std::vector<double> row_gain;  // the gain on each block row (empty: `gain` on every row)
  double gain_at(int block_row) const;
};

struct ExposureDrift {
  std::vector<PhotoExposure> photos;  // one per capture of the series; empty: not estimated
  int reference_blocks = 0;           // unmodulated blocks the fit used
  bool offset_fitted = false;         // their levels spread enough to fit an offset too
  // Spline segments over the image height of the row-dependent gain; 0: one gain per photo
  // (the row fit was not asked for, or the references left a segment uncovered).
  int row_segments = 0;
  double max_gain_change() const;     // max |gain - 1| over the photos and their rows
  double max_row_variation() const;   // max over photos of (max - min) / 2 of the row gain
};

struct ExposureDriftOptions {
  int min_reference_blocks = 20;
  // A block is a reference when no step's level strays from its mean by more than this
  // fraction (after first corrections with 4x and 2x looser bounds, since the drift itself
  // moves the levels). Its levels, not its phasor: a block whose steps are out of order can
  // have a small phasor and still change from step to step.
  double max_reference_spread = 0.03;
  // The row-dependent gain: cubic B-spline segments over the image height (24: banding of up
  // to ~5 bands over the height; 0: one gain per photo), each segment needing this many
  // reference blocks.
  int row_segments = 24;
  int min_references_per_segment = 8;
};

// Empty `photos` when too few unmodulated blocks were seen (nothing to correct with).
ExposureDrift estimate_exposure_drift(const BlockPhasors& phasors,
                                      const ExposureDriftOptions& options = {});
// Divides the drift out of the block levels and rebuilds the phasor sums from them.
void remove_exposure_drift(BlockPhasors& phasors, const ExposureDrift& drift);
// Divides one photo's exposure out of its block means (any number of channels; row r of
// `level` is block row r): (level - offset) / gain(row). Returns a new matrix.
cv::Mat divide_exposure(const cv::Mat& level, const PhotoExposure& exposure);

}  // namespace lfd::calib
