#include "record/interrupt.hpp"

#include <csignal>

namespace lfd::record {
namespace {

std::atomic<bool> g_stop{false};
struct sigaction g_previous_int, g_previous_term;

void on_signal(int signal) {
  g_stop.store(true);
  // The next one is the default: a second Ctrl-C ends the program at once.
  std::signal(signal, SIG_DFL);
}

}  // namespace

StopRequest::StopRequest() {
  g_stop.store(false);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

StopRequest::~StopRequest() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

const std::atomic<bool>& StopRequest::flag() { return g_stop; }

}  // namespace lfd::record
