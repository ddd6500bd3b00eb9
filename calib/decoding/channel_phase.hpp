#pragma once
// The phase each colour channel decodes on its own (docs/calibration.md, 3.7: colour order and
// subpixel cells are checked, not trusted). Phase decoding sums the three channels' phasors, which
// is right only if each subpixel sits where the display description says: the pattern gave every
// subpixel the nominal phase of its described position, so a channel whose subpixels sit elsewhere
// (BGR taken for RGB, a wrong Gen3 cell table) decodes the phase of that other position, a constant
// offset of pitch' times the displacement across the lens lines. Per block, each channel's phasor
// sum_k I_ck exp(2 pi i k/K) gives its own phase; what is kept is its offset from the all-channel
// phase and its share of the all-channel amplitude.
#include <array>
#include <vector>

#include <opencv2/core.hpp>

#include "calib/phasors/exposure_drift.hpp"

namespace lfd::calib {

// One phase sample's channels (R, G, B).
struct ChannelPhase {
  std::array<float, 3> offset_periods{0, 0, 0};  // channel phase minus psi, in [-1/2, 1/2)
  std::array<float, 3> weight{0, 0, 0};          // |z_c| / sum of |z_c|
};

// Per-channel phasors of a K-step series, summed over blocks of camera pixels with the
// photos' exposure drift divided out (the same blocks as block_phasors).
class ChannelPhasors {
 public:
  ChannelPhasors(const std::vector<cv::Mat>& captures, int block_px, const ExposureDrift& drift);
  // The channels of block (bx, by) against the all-channel phase psi.
  ChannelPhase at(int bx, int by, double psi) const;

 private:
  std::array<cv::Mat, 3> re_, im_;  // CV_32F, blocks
};

// psi with each channel's phasor turned back by `shift_periods[c]` before the channels are
// summed again: the phase the samples would have decoded had the pattern used the subpixel
// positions that predict those shifts (colour_order.hpp).
double reweighted_phase(double psi, const ChannelPhase& channels,
                        const std::array<double, 3>& shift_periods);

}  // namespace lfd::calib
