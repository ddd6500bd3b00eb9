#include "util/progress.hpp"

#include <chrono>
#include <cstdio>
#include <unistd.h>

namespace lfd {
namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Progress::Progress(std::string label, long total)
    : label_(std::move(label)), total_(total > 0 ? total : 1), enabled_(isatty(2) != 0) {}

Progress::Progress(std::string label, long total, std::string unit) : Progress(std::move(label), total) {
  unit_ = std::move(unit);
  start_s_ = now_s();
}

Progress::~Progress() { finish(); }

void Progress::advance(long n) {
  const long done = done_.fetch_add(n) + n;
  if (!unit_.empty()) {  // few, slow steps: each one redrawn
    draw(done);
    return;
  }
  const int percent = int(100 * done / total_);
  int last = last_percent_.load();
  if (percent != last && last_percent_.compare_exchange_strong(last, percent)) draw(done);
}

void Progress::draw(long done) {
  if (!enabled_) return;
  const int width = 30;
  const int filled = int(width * done / total_);
  std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%", label_.c_str(), filled,
               "##############################", width - filled, "", int(100 * done / total_));
  if (!unit_.empty() && done > 0) {
    const double elapsed = now_s() - start_s_, rate = done / elapsed;
    const long left_s = long((total_ - done) / rate + 0.5);
    std::fprintf(stderr, " %ld/%ld  %.2f %s/s  %ld:%02ld left ", done, total_, rate, unit_.c_str(), left_s / 60,
                 left_s % 60);
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (enabled_) {
    draw(unit_.empty() ? total_ : done_.load());
    std::fprintf(stderr, "\n");
  }
}

}  // namespace lfd
