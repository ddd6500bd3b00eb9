#include "util/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace lfd {

Progress::Progress(std::string label, long total)
    : label_(std::move(label)), total_(total > 0 ? total : 1), enabled_(isatty(2) != 0) {}

Progress::~Progress() { finish(); }

void Progress::advance(long n) {
  const long done = done_.fetch_add(n) + n;
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
  std::fflush(stderr);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (enabled_) {
    draw(total_);
    std::fprintf(stderr, "\n");
  }
}

}  // namespace lfd
