#pragma once
// SIGINT and SIGTERM for `lfd serve` (docs/serve.md, "Stopping"): the first asks the main loop to
// stop (requested()); if the process has not ended `grace` later (a frame decoding a large
// file, a worker in the middle of a request, connections in keep-alive), what is still running
// is abandoned and the process exits at once with status 0, so systemd's stop never needs
// SIGKILL. What the service keeps on disk is written atomically (the playlist state file,
// util/atomic_file.hpp: a temporary file renamed over the old one), so an exit at any moment
// leaves the old file or the new one, whole. One per process.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace lfd::serve {

class StopOnSignal {
 public:
  explicit StopOnSignal(std::chrono::milliseconds grace);
  ~StopOnSignal();  // the orderly end: the deadline no longer applies
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  bool requested() const;
  void request();  // as a signal does (a window closed)

 private:
  void watch();

  std::chrono::milliseconds grace_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool ended_ = false;
  std::thread watch_;
};

}  // namespace lfd::serve
