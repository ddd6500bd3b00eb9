// The service under load on real loopback sockets, against the test double (docs/serve.md,
// "Memory"): shows over the memory budget are answered busy at once and the process's resident
// memory (from /proc) stays within the budget and a margin; cheap requests answer while shows
// are refused. The bounds are generous: they separate a bounded service from one that holds
// every request, not fast from slow.
#include <atomic>
#include <cstdio>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>
#include <httplib.h>

#include "serve/memory_budget.hpp"
#include "serve/service.hpp"
#include "tests/serve/fake_display_service.hpp"
#include "tests/serve/serve_test_support.hpp"

namespace lfd::serve {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr int kSide = 1536;  // 6.75 MiB as RGB: a decode holds 13.5 MiB
constexpr std::size_t kBudget = 32u << 20;

// `count` different quilts as PNG: every one decodes (decoding happens once per content).
std::vector<std::vector<std::uint8_t>> distinct_quilts(int count, const std::filesystem::path& dir) {
  std::vector<std::vector<std::uint8_t>> out;
  for (int k = 0; k < count; ++k) {
    Image8 image = test::pattern_quilt(kSide, kSide);
    for (std::size_t i = 0; i < image.pixels.size(); i += 3) image.pixels[i] = static_cast<std::uint8_t>(image.pixels[i] + 37 * k);
    out.push_back(test::png_bytes(image, dir));
  }
  return out;
}

json show_cmd() {
  return {{"show", {{"source", "bindata"}, {"quilt", {{"type", "image"}, {"settings", {{"vx", 4}, {"vy", 4}, {"aspect", 1.0}}}}}}}};
}

struct Replies {
  std::atomic<int> ok{0}, busy{0}, other{0}, none{0};
  void count(const std::optional<json>& reply) {
    if (!reply) ++none;
    else if ((*reply)["error"] == 0) ++ok;
    else if ((*reply)["error"] == 6) ++busy;
    else ++other;
  }
};

struct ServiceUnderLoadTest : ::testing::Test {
  test::FakeDisplayService fake{{test::fixture_display()}};
  ServeOptions options;
  std::unique_ptr<Service> service;
  test::TempDir tmp;

  void start(ServeLimits limits) {
    return_large_buffers_to_the_system();  // as lfd serve does, so RSS follows what is held
    options.limits = limits;
    options.listen = {"127.0.0.1", test::free_port(), test::free_port(), test::free_port()};
    service = std::make_unique<Service>(fake, options);
    service->start();
  }

  // `threads` clients, each showing the quilts in turn (from its own offset): `shows_each`
  // shows, or (0) until `until`.
  void flood(const std::vector<std::vector<std::uint8_t>>& quilts, int threads, Clock::time_point until,
             int shows_each, Replies& replies) {
    std::vector<std::thread> clients;
    for (int t = 0; t < threads; ++t)
      clients.emplace_back([&, t] {
        test::HoloPlayClient client(options.listen.holoplay_port, 10000);
        for (int i = 0; shows_each > 0 ? i < shows_each : Clock::now() < until; ++i)
          replies.count(client.request(show_cmd(), quilts[(t + i) % quilts.size()]));
      });
    for (auto& c : clients) c.join();
  }
};

TEST_F(ServiceUnderLoadTest, ShowsOverTheBudgetAreAnsweredBusyAndMemoryStaysUnderIt) {
  ServeLimits limits;
  limits.memory_budget_bytes = kBudget;
  limits.worker_threads = 8;  // eight decodes at once would need 108 MiB: the budget decides
  limits.max_decodes = 8;
  limits.decoded_quilts_kept = 1;
  start(limits);
  const auto quilts = distinct_quilts(8, tmp.path);
  test::ResidentGrowth growth;
  Replies replies;
  flood(quilts, 8, Clock::now(), 4, replies);
  const double grown_mib = growth.stop();
  EXPECT_EQ(replies.none.load(), 0);   // every show answered
  EXPECT_EQ(replies.other.load(), 0);  // shown or busy, nothing else
  EXPECT_GT(replies.busy.load(), 0);
  EXPECT_GT(replies.ok.load(), 0);
  std::printf("busy %d, shown %d; resident memory grew by %.1f MiB at most (budget %zu MiB)\n", replies.busy.load(),
              replies.ok.load(), grown_mib, kBudget >> 20);
  EXPECT_LT(grown_mib, kBudget / double(1 << 20) + 48) << "resident memory grew by " << grown_mib << " MiB";
  EXPECT_LE(service->budget().used(), std::size_t(kSide) * kSide * 3);  // only the one picture kept
}

TEST_F(ServiceUnderLoadTest, CheapRequestsAnswerWhileShowsAreRefused) {
  ServeLimits limits;  // the shipped workers and decoder
  limits.memory_budget_bytes = kBudget;
  limits.decoded_quilts_kept = 1;  // so the shows keep needing decodes
  start(limits);
  const auto quilts = distinct_quilts(4, tmp.path);
  Replies shows;
  const auto until = Clock::now() + std::chrono::milliseconds(1500);
  std::thread flooding([&] { flood(quilts, 8, until, 0, shows); });
  httplib::Client bridge("127.0.0.1", options.listen.bridge_port);
  bridge.set_read_timeout(5, 0);
  const auto token = json::parse(bridge.Put("/enter_orchestration", "{}", "application/json")->body)["payload"]["value"];
  test::HoloPlayClient holoplay(options.listen.holoplay_port, 5000);
  double slowest_ms = 0;
  int cheap = 0;
  while (Clock::now() < until) {
    const auto t0 = Clock::now();
    const auto info = holoplay.request({{"info", json::object()}});
    ASSERT_TRUE(info);
    EXPECT_EQ((*info)["error"], 0);
    const auto devices = bridge.Put("/available_output_devices", json{{"orchestration", token}}.dump(), "application/json");
    ASSERT_TRUE(devices);
    EXPECT_EQ(devices->status, 200);
    slowest_ms = std::max(slowest_ms, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    ++cheap;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  flooding.join();
  EXPECT_GT(shows.busy.load(), 0);  // shows were being refused meanwhile
  EXPECT_EQ(shows.none.load(), 0);
  EXPECT_GE(cheap, 3);
  EXPECT_LT(slowest_ms, 2000) << "an info + Bridge query took " << slowest_ms << " ms";
}

}  // namespace
}  // namespace lfd::serve
