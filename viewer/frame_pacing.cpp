#include "viewer/frame_pacing.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lfd::viewer {

void FramePacing::add(double interval_s) {
  intervals_.push_back(interval_s);
  if (intervals_.size() > window_) intervals_.pop_front();
}

PacingFigures FramePacing::figures() const {
  PacingFigures f;
  f.frames = intervals_.size();
  if (intervals_.empty()) return f;
  std::vector<double> sorted(intervals_.begin(), intervals_.end());
  std::sort(sorted.begin(), sorted.end());
  const size_t n = sorted.size();
  f.median_s = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  // Nearest rank: the smallest interval at or above 99 % of them.
  const size_t rank = size_t(std::ceil(0.99 * double(n)));
  f.p99_s = sorted[std::max<size_t>(rank, 1) - 1];
  return f;
}

}  // namespace lfd::viewer
