// The service in a process of its own, stopped by a signal as `lfd serve` is
// (tests/serve/stop_test.cpp): the Service on a display that never finishes showing (every
// `show` holds its worker, so requests pile up behind them), the playlists in a state file, the
// stop of serve/stop_on_signal.hpp and the same main loop shape as apps/serve.cpp.
//   lfd_serve_stop_child CALIBRATION STATE_FILE HOLOPLAY_PORT BRIDGE_PORT EVENTS_PORT
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "serve/served_display.hpp"
#include "serve/service.hpp"
#include "serve/stop_on_signal.hpp"
#include "tests/serve/fake_display_service.hpp"

namespace {

// A display whose frames never come: show_quilt does not return for a minute.
struct StuckDisplay : lfd::serve::test::FakeDisplayService {
  using FakeDisplayService::FakeDisplayService;
  void show_quilt(int, const lfd::Image8&, const lfd::serve::QuiltSettings&, const std::string&) override {
    std::this_thread::sleep_for(std::chrono::seconds(60));
  }
};

}  // namespace

int main(int argc, char** argv) {
  using namespace lfd::serve;
  if (argc != 6) {
    std::fprintf(stderr, "usage: %s CALIBRATION STATE_FILE HOLOPLAY_PORT BRIDGE_PORT EVENTS_PORT\n", argv[0]);
    return 2;
  }
  StopOnSignal stop(std::chrono::milliseconds(1000));
  StuckDisplay display({served_display_from_file(0, argv[1])});
  ServeOptions options;
  options.state_file = argv[2];
  options.listen = {"127.0.0.1", std::stoi(argv[3]), std::stoi(argv[4]), std::stoi(argv[5])};
  Service service(display, options);
  service.start();
  std::printf("ready\n");
  std::fflush(stdout);
  while (!stop.requested()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  service.stop();  // waits for the stuck workers: the stop's deadline ends the process first
  return 0;
}
