#pragma once
// A text progress bar on stderr for long work; silent when stderr is not a terminal
// (CI logs, pipes) so logs stay readable.
#include <atomic>
#include <string>

namespace lfd {

class Progress {
 public:
  Progress(std::string label, long total);
  // With a `unit` ("frames"): every step redrawn with the count, the rate and the time left,
  // "label [####    ] 12/100  3.4 frames/s  0:26 left".
  Progress(std::string label, long total, std::string unit);
  ~Progress();
  void advance(long n = 1);  // thread-safe
  void finish();

 private:
  void draw(long done);
  std::string label_, unit_;
  long total_;
  double start_s_ = 0.0;
  std::atomic<long> done_{0};
  std::atomic<int> last_percent_{-1};
  bool enabled_;
  bool finished_ = false;
};

}  // namespace lfd
