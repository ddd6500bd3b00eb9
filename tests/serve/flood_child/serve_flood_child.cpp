// HoloPlay clients in a process of their own (tests/serve/holoplay_reception_test.cpp), so the
// test measures the service's resident memory without the clients' copies of what they send:
// CLIENTS connections each send one `show` carrying BYTES of content at the same moment, then
// an `info`, and the replies are counted on one line.
//   lfd_serve_flood_child HOLOPLAY_PORT CLIENTS BYTES
#include <atomic>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "tests/serve/serve_test_support.hpp"

int main(int argc, char** argv) {
  using nlohmann::json;
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s HOLOPLAY_PORT CLIENTS BYTES\n", argv[0]);
    return 2;
  }
  const int port = std::stoi(argv[1]), clients = std::stoi(argv[2]);
  const std::vector<std::uint8_t> content(std::stoul(argv[3]), 0x5a);  // not a picture: never decoded
  const json show = {{"show", {{"source", "bindata"}, {"quilt", {{"type", "image"}, {"settings", {{"vx", 4}, {"vy", 4}, {"aspect", 1.0}}}}}}}};
  std::atomic<int> ready{0}, ok{0}, busy{0}, other{0}, none{0}, info{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < clients; ++i)
    threads.emplace_back([&] {
      lfd::serve::test::HoloPlayClient client(port, 20000);
      if (++ready < clients)  // every connection made before any sends: they arrive together
        while (ready < clients) std::this_thread::yield();
      const auto reply = client.request(show, content);
      if (!reply) ++none;
      else if ((*reply)["error"] == 0) ++ok;
      else if ((*reply)["error"] == 6) ++busy;
      else ++other;
      const auto answer = client.request({{"info", json::object()}});
      if (answer && (*answer)["error"] == 0) ++info;
    });
  for (auto& t : threads) t.join();
  std::printf("ok %d busy %d other %d none %d info %d\n", ok.load(), busy.load(), other.load(), none.load(), info.load());
  return 0;
}
