#pragma once
// Frame pacing: the wall-clock intervals between the viewer's frames, their median and 99th
// percentile over a window of recent frames (the control window shows both; a scripted run
// prints them at exit, which is how `lfd view --no-vsync --frames N` measures a frame). The
// median says the frame rate, the p99 the stalls a median hides (docs/viewer.md).
#include <cstddef>
#include <deque>

namespace lfd::viewer {

struct PacingFigures {
  double median_s = 0, p99_s = 0;
  size_t frames = 0;  // intervals in the window
};

class FramePacing {
 public:
  explicit FramePacing(size_t window = 300) : window_(window) {}
  void add(double interval_s);
  PacingFigures figures() const;  // zeros before the first interval

 private:
  size_t window_;
  std::deque<double> intervals_;
};

}  // namespace lfd::viewer
