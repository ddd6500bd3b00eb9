#include "live/console_prompt.hpp"

#include <poll.h>
#include <unistd.h>

#include <cstdio>

#include "util/error.hpp"

namespace lfd::live {

void wait_for_enter(const std::string& prompt, const std::function<bool()>& poll) {
  std::fprintf(stderr, "%s ", prompt.c_str());
  std::fflush(stderr);
  // stdin byte by byte after poll(2), without stdio's buffer, so it never blocks the window.
  for (;;) {
    pollfd in{STDIN_FILENO, POLLIN, 0};
    if (::poll(&in, 1, 50) > 0) {
      char c = 0;
      if (::read(STDIN_FILENO, &c, 1) <= 0)
        throw_input_error("stdin closed while waiting for Enter ({}); run --live from a terminal",
                          prompt);
      if (c == '\n') return;
    }
    if (poll && poll()) {
      std::fputc('\n', stderr);
      return;
    }
  }
}

}  // namespace lfd::live
