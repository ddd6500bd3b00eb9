#pragma once
// Repeated timings summarised robustly: the median and the spread (min, max and the median
// absolute deviation), as the benchmarks report them.
#include <vector>

#include <nlohmann/json.hpp>

namespace lfd::bench {

struct TimingStats {
  std::vector<double> samples;  // in the order measured
  double median = 0, min = 0, max = 0;
  double mad = 0;  // median absolute deviation from the median

  // {median, min, max, mad, samples}
  nlohmann::ordered_json to_json() const;
};

// The statistics of `samples` (empty: all zero).
TimingStats summarize(std::vector<double> samples);

}  // namespace lfd::bench
