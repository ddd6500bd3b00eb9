#pragma once
// Fixtures of the serve tests: a served display from a real unit's visual.json, a small PNG
// quilt in memory, a temporary folder, a free loopback port, a HoloPlay client.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

#include <nng/nng.h>
#include <nng/protocol/reqrep0/req.h>
#include <nlohmann/json.hpp>

#include "serve/cbor_json.hpp"

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "serve/memory_budget.hpp"
#include "serve/served_display.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace lfd::serve::test {

inline ServedDisplay fixture_display() {
  return served_display_from_file(0, lfd::test::fixture_calibration("LKG-PORT-portrait.visual.json"));
}

// A quilt whose pixels say where they are, so a decoded copy can be compared exactly.
inline Image8 pattern_quilt(int w, int h) {
  Image8 image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto* p = &image.pixels[(static_cast<size_t>(y) * w + x) * 3];
      p[0] = static_cast<uint8_t>(x * 7);
      p[1] = static_cast<uint8_t>(y * 5);
      p[2] = static_cast<uint8_t>((x + y) * 3);
    }
  return image;
}

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string t = (std::filesystem::temp_directory_path() / "lfd-serve-test-XXXXXX").string();
    path = mkdtemp(t.data());
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

inline std::vector<std::uint8_t> png_bytes(const Image8& image, const std::filesystem::path& dir) {
  const auto file = dir / "quilt.png";
  write_png(file, image);
  std::vector<std::uint8_t> bytes(std::filesystem::file_size(file));
  std::FILE* f = std::fopen(file.c_str(), "rb");
  const size_t n = std::fread(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  bytes.resize(n);
  return bytes;
}

// A port nothing listens on now (the kernel's choice).
inline int free_port() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t n = sizeof a;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &n);
  ::close(s);
  return ntohs(a.sin_port);
}

// One HoloPlay connection kept open (as holoplay-core keeps its own): NNG's REQ socket over
// WebSocket. request() gives the reply map, or nothing when none came within the timeout.
struct HoloPlayClient {
  nng_socket socket{};
  HoloPlayClient(int port, int timeout_ms) {
    nng_req0_open(&socket);
    nng_socket_set_ms(socket, NNG_OPT_RECVTIMEO, timeout_ms);
    nng_socket_set_ms(socket, NNG_OPT_SENDTIMEO, timeout_ms);
    nng_socket_set_ms(socket, NNG_OPT_REQ_RESENDTIME, 0);
    nng_dial(socket, ("ws://localhost:" + std::to_string(port) + "/driver").c_str(), nullptr, 0);
  }
  ~HoloPlayClient() { nng_close(socket); }
  HoloPlayClient(const HoloPlayClient&) = delete;
  HoloPlayClient& operator=(const HoloPlayClient&) = delete;

  std::optional<nlohmann::json> request(const nlohmann::json& cmd, const std::vector<std::uint8_t>& bin = {}) {
    const auto bytes =
        encode_cbor({{"cmd", cmd}, {"bin", bin.empty() ? nlohmann::json(nullptr) : nlohmann::json::binary(bin)}});
    nng_msg* m = nullptr;
    nng_msg_alloc(&m, 0);
    nng_msg_append(m, bytes.data(), bytes.size());
    if (nng_sendmsg(socket, m, 0) != 0) {
      nng_msg_free(m);
      return std::nullopt;
    }
    if (nng_recvmsg(socket, &m, 0) != 0) return std::nullopt;
    nlohmann::json reply = decode_cbor({static_cast<const std::uint8_t*>(nng_msg_body(m)), nng_msg_len(m)}, {});
    nng_msg_free(m);
    return reply;
  }
};

// This process's resident memory sampled every 2 ms from construction to stop(): how much it
// grew at most (MiB), for the tests that bound what the service holds.
class ResidentGrowth {
 public:
  ResidentGrowth() : start_(resident_bytes()), peak_(start_), sampler_([this] {
    while (!done_) {
      peak_ = std::max<std::size_t>(peak_, resident_bytes());
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }) {}
  ~ResidentGrowth() { stop(); }
  double stop() {
    done_ = true;
    if (sampler_.joinable()) sampler_.join();
    return (double(peak_) - double(start_)) / (1 << 20);
  }

 private:
  std::size_t start_;
  std::atomic<std::size_t> peak_;
  std::atomic<bool> done_{false};
  std::thread sampler_;
};

}  // namespace lfd::serve::test
