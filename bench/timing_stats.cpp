#include "bench/timing_stats.hpp"

#include <algorithm>
#include <cmath>

namespace lfd::bench {
namespace {

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

TimingStats summarize(std::vector<double> samples) {
  TimingStats s;
  s.samples = std::move(samples);
  if (s.samples.empty()) return s;
  s.median = median_of(s.samples);
  s.min = *std::min_element(s.samples.begin(), s.samples.end());
  s.max = *std::max_element(s.samples.begin(), s.samples.end());
  std::vector<double> deviation;
  for (double x : s.samples) deviation.push_back(std::fabs(x - s.median));
  s.mad = median_of(deviation);
  return s;
}

nlohmann::ordered_json TimingStats::to_json() const {
  return {{"median", median}, {"min", min}, {"max", max}, {"mad", mad}, {"samples", samples}};
}

}  // namespace lfd::bench
