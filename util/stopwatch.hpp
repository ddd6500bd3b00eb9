#pragma once
// The one wall-clock stopwatch of lfd (as COLMAP's util/timer.h): started when made, read in
// seconds as a double, restarted where a loop times each pass. steady_clock, so a clock change
// during a benchmark cannot make a time negative.
#include <chrono>

namespace lfd {

class Stopwatch {
 public:
  using Clock = std::chrono::steady_clock;

  Stopwatch() : start_(Clock::now()) {}

  // Seconds since it was made or last restarted.
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  void restart() { start_ = Clock::now(); }

 private:
  Clock::time_point start_;
};

}  // namespace lfd
