// Stopping lfd serve promptly (docs/serve.md, "Stopping").
#include "serve/stop_on_signal.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>

namespace lfd::serve {

namespace {
std::atomic<bool> stop_requested{false};
extern "C" void on_stop_signal(int) { stop_requested = true; }  // async-signal-safe: one store
}  // namespace

StopOnSignal::StopOnSignal(std::chrono::milliseconds grace) : grace_(grace) {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  watch_ = std::thread([this] { watch(); });
}

StopOnSignal::~StopOnSignal() {
  {
    std::lock_guard lock(mutex_);
    ended_ = true;
  }
  wake_.notify_all();
  watch_.join();
}

bool StopOnSignal::requested() const { return stop_requested; }

void StopOnSignal::request() {
  stop_requested = true;
  wake_.notify_all();
}

// Polls the flag (a signal handler cannot notify a condition variable), then gives the orderly
// stop its grace.
void StopOnSignal::watch() {
  std::unique_lock lock(mutex_);
  while (!ended_ && !stop_requested) wake_.wait_for(lock, std::chrono::milliseconds(10));
  if (ended_) return;
  if (wake_.wait_for(lock, grace_, [&] { return ended_; })) return;
  static const char message[] = "lfd serve: stopping took too long; work in flight abandoned, exiting now\n";
  [[maybe_unused]] auto n = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(0);
}

}  // namespace lfd::serve
