#pragma once
// Phase-shifting sums per block of camera pixels, shared by the phase decoding (view fraction)
// and the fringe decoding (dense registration). For K captures I_k = a + b cos(2 pi (t - k/K)),
//   z = sum_k I_k exp(2 pi i k / K) = (K / 2) b exp(2 pi i t),
// summed over the three channels and over the block's pixels before the argument is taken
// (the block sum averages lens-scale moire and sensor noise without biasing the phase).
// Saturated pixels (glare, specular reflections) carry no phase: they are left out of the sums.
#include <vector>

#include <opencv2/core.hpp>

namespace lfd::calib {

struct BlockPhasors {
  cv::Size blocks;                // blocks across and down
  int block_px = 1;
  cv::Mat re, im;                 // CV_32F, z summed over channels, mean over valid pixels
  cv::Mat mean;                   // mean level a per channel (valid pixels)
  cv::Mat valid;                  // fraction of the block's pixels not saturated
  std::vector<cv::Mat> level;     // per capture: mean level of the block (valid pixels)

  cv::Point2f centre_px(int bx, int by) const {
    return {bx * block_px + 0.5f * block_px - 0.5f, by * block_px + 0.5f * block_px - 0.5f};
  }
  // Wrapped phase t in [0, 1) and modulation b / a of a block (valid fraction > 0). With 6 or
  // more steps the phase leaves out up to three that something transient (glare that comes
  // and goes, a reflection of someone walking by) pushed off the sinusoid: a step goes only if
  // its residual dominates (> 3x the median) and is large against the modulation (> b / 8), so
  // the harmonics of the camera response, spread over all steps alike, keep cancelling.
  double phase(int bx, int by) const;
  double modulation(int bx, int by, int steps) const;
};

// `captures[k]` is the capture of step k: CV_32FC3, values in [0, 1].
BlockPhasors block_phasors(const std::vector<cv::Mat>& captures, int block_px);

}  // namespace lfd::calib
