// SIGTERM ends the service within 2 s whatever is queued, and the playlist state file reads back
// whole (serve/stop_on_signal.hpp, docs/serve.md "Stopping"). The service runs in a process of
// its own (tests/serve/stop_child) on a display that never finishes a show, so every HoloPlay
// worker is held and more shows wait behind them, while a Bridge client keeps changing
// playlists (each change rewrites the state file) as the signal comes.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>
#include <httplib.h>

#include "serve/listen_address.hpp"
#include "serve/playlist_store.hpp"
#include "tests/serve/serve_test_support.hpp"
#include "util/atomic_file.hpp"

namespace lfd::serve {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

TEST(ServiceStop, SigtermWithAFullQueueExitsWithinTwoSecondsAndTheStateFileReadsBackWhole) {
  test::TempDir tmp;
  const auto state_file = tmp.path / "state" / "playlists.json";
  const auto quilt_file = tmp.path / "q.png";
  write_png(quilt_file, test::pattern_quilt(64, 64));
  const std::vector<std::uint8_t> quilt = test::png_bytes(test::pattern_quilt(256, 256), tmp.path);
  const ListenAddress address{"127.0.0.1", test::free_port(), test::free_port(), test::free_port()};
  const std::string calibration = test::fixture_display().calibration_path.string();
  const std::string ports[] = {std::to_string(address.holoplay_port), std::to_string(address.bridge_port),
                               std::to_string(address.events_port)};
  int out[2];
  ASSERT_EQ(::pipe(out), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // exec at once: nothing of this process's threads is used after fork
    ::dup2(out[1], STDOUT_FILENO);
    ::execl(LFD_SERVE_STOP_CHILD, LFD_SERVE_STOP_CHILD, calibration.c_str(), state_file.c_str(), ports[0].c_str(),
            ports[1].c_str(), ports[2].c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  char ready[6] = {};
  ASSERT_EQ(::read(out[0], ready, 5), 5) << "the service did not start";
  ASSERT_STREQ(ready, "ready");

  httplib::Client bridge("127.0.0.1", address.bridge_port);
  bridge.set_read_timeout(3, 0);
  const auto token = json::parse(bridge.Put("/enter_orchestration", "{}", "application/json")->body)["payload"]["value"];
  const auto make_playlist = [&](int k) {
    const std::string name = "p" + std::to_string(k);
    bridge.Put("/instance_playlist", json{{"orchestration", token}, {"name", name}}.dump(), "application/json");
    bridge.Put("/insert_playlist_entry",
               json{{"orchestration", token}, {"name", name}, {"uri", "file://" + quilt_file.string()}, {"rows", 2},
                    {"cols", 2}, {"aspect", 1.0}}
                   .dump(),
               "application/json");
  };
  for (int k = 0; k < 10; ++k) make_playlist(k);
  // The queue: eight clients' shows, four of them holding the workers on the stuck display.
  std::atomic<bool> stopped{false};
  std::vector<std::thread> clients;
  for (int t = 0; t < 8; ++t)
    clients.emplace_back([&] {
      test::HoloPlayClient holoplay(address.holoplay_port, 500);
      while (!stopped)
        holoplay.request({{"show", {{"source", "bindata"}, {"quilt", {{"settings", {{"vx", 4}, {"vy", 4}}}}}}}}, quilt);
    });
  std::thread writer([&] {  // playlists changing as the signal comes
    for (int k = 10; !stopped; ++k) make_playlist(10 + k % 20);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));

  const auto signalled = Clock::now();
  ASSERT_EQ(::kill(child, SIGTERM), 0);
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(child, &status, WNOHANG)) == 0 && Clock::now() - signalled < std::chrono::seconds(10))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const double stop_s = std::chrono::duration<double>(Clock::now() - signalled).count();
  stopped = true;
  writer.join();
  for (auto& c : clients) c.join();
  ::close(out[0]);
  if (done == 0) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
  }
  ASSERT_EQ(done, child) << "still running " << stop_s << " s after SIGTERM";
  EXPECT_LT(stop_s, 2.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);

  // Whole: valid JSON of the store's format, every playlist made before the flood with its entry.
  const json root = json::parse(read_text_file(state_file));
  EXPECT_EQ(root["format"], "lfd-serve-playlists");
  ServeLimits limits;
  PlaylistStore store(state_file, limits);
  EXPECT_GE(store.size(), 10u);
  for (int k = 0; k < 10; ++k) {
    const auto playlist = store.get("p" + std::to_string(k));
    ASSERT_TRUE(playlist) << "p" << k;
    EXPECT_EQ(playlist->entries.size(), 1u);
  }
}

}  // namespace
}  // namespace lfd::serve
