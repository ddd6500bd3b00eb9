#include "calib/exposure_drift.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::calib {

namespace {

// The blocks fully valid (nothing saturated) whose levels stay within `max_spread` of their
// mean in every step; of the median block's mean for darker blocks, which an offset drift
// moves by more than their own level allows.
std::vector<cv::Point> unmodulated_blocks(const BlockPhasors& p, double max_spread) {
  std::vector<float> means;
  for (int by = 0; by < p.blocks.height; ++by)
    for (int bx = 0; bx < p.blocks.width; ++bx)
      if (p.valid.at<float>(by, bx) > 0.999f) means.push_back(p.mean.at<float>(by, bx));
  if (means.empty()) return {};
  std::nth_element(means.begin(), means.begin() + long(means.size() / 2), means.end());
  const float typical = means[means.size() / 2];
  std::vector<cv::Point> out;
  for (int by = 0; by < p.blocks.height; ++by)
    for (int bx = 0; bx < p.blocks.width; ++bx) {
      const float mean = p.mean.at<float>(by, bx);
      if (!(p.valid.at<float>(by, bx) > 0.999f && mean > 1e-4f)) continue;
      float spread = 0;
      for (const auto& level : p.level)
        spread = std::max(spread, std::abs(level.at<float>(by, bx) - mean));
      if (spread < max_spread * std::max(mean, typical)) out.emplace_back(bx, by);
    }
  return out;
}

// Least squares level_k = g_k ref + o_k over the reference blocks, ref = the block's mean
// level; gain only (o_k = 0) when the references are all about as bright (no lever arm).
ExposureDrift fit_drift(const BlockPhasors& p, const std::vector<cv::Point>& blocks) {
  ExposureDrift out;
  out.reference_blocks = int(blocks.size());
  double lo = 1e9, hi = -1e9, sum_r = 0, sum_rr = 0;
  for (const auto& b : blocks) {
    const double r = p.mean.at<float>(b);
    lo = std::min(lo, r), hi = std::max(hi, r), sum_r += r, sum_rr += r * r;
  }
  const double n = double(blocks.size());
  const double var_r = sum_rr / n - (sum_r / n) * (sum_r / n);
  out.offset_fitted = hi - lo > 0.3 * hi && var_r > 0;
  for (const auto& level : p.level) {
    double sum_l = 0, sum_rl = 0;
    for (const auto& b : blocks) {
      const double l = level.at<float>(b);
      sum_l += l, sum_rl += p.mean.at<float>(b) * l;
    }
    PhotoExposure e;
    if (out.offset_fitted) {
      e.gain = (sum_rl / n - (sum_r / n) * (sum_l / n)) / var_r;
      e.offset = sum_l / n - e.gain * sum_r / n;
    } else {
      e.gain = sum_rl / sum_rr;
    }
    out.photos.push_back(e);
  }
  return out;
}

}  // namespace

double ExposureDrift::max_gain_change() const {
  double m = 0;
  for (const auto& p : photos) m = std::max(m, std::abs(p.gain - 1));
  return m;
}

ExposureDrift estimate_exposure_drift(const BlockPhasors& phasors,
                                      const ExposureDriftOptions& options) {
  // The drift itself moves every level, so the first pass admits more and the second chooses
  // again on the corrected levels.
  auto blocks = unmodulated_blocks(phasors, 3 * options.max_reference_spread);
  if (int(blocks.size()) < options.min_reference_blocks) return {};
  const ExposureDrift first = fit_drift(phasors, blocks);
  BlockPhasors corrected = phasors;
  remove_exposure_drift(corrected, first);
  blocks = unmodulated_blocks(corrected, options.max_reference_spread);
  if (int(blocks.size()) < options.min_reference_blocks) return first;
  return fit_drift(phasors, blocks);
}

void remove_exposure_drift(BlockPhasors& p, const ExposureDrift& drift) {
  const int K = int(p.level.size());
  if (drift.photos.size() != size_t(K)) return;
  const double two_pi = 2.0 * std::numbers::pi;
  cv::Mat re(p.blocks, CV_32F, 0.0f), im(p.blocks, CV_32F, 0.0f), mean(p.blocks, CV_32F, 0.0f);
  for (int k = 0; k < K; ++k) {
    // A new matrix, not in place: copies of a BlockPhasors share their levels' pixels.
    const PhotoExposure& e = drift.photos[size_t(k)];
    cv::Mat level;
    p.level[size_t(k)].convertTo(level, CV_32F, 1.0 / e.gain, -e.offset / e.gain);
    p.level[size_t(k)] = level;
    // The sums block_phasors makes: three channels' z over the block's valid pixels.
    re += level * float(3.0 * std::cos(two_pi * k / K));
    im += level * float(3.0 * std::sin(two_pi * k / K));
    mean += level * float(1.0 / K);
  }
  p.re = re;
  p.im = im;
  p.mean = mean;
}

}  // namespace lfd::calib
