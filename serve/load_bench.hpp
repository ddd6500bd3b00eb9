#pragma once
// `lfd bench serve` (docs/serve.md, "Load"): many clients at once against a running lfd serve on
// loopback for a fixed time: HoloPlay info and quilt shows over NNG's WebSocket REQ socket (the
// framing holoplay-core speaks), Bridge calls and casts over HTTP, event sockets, and clients
// that vanish mid-connection. Counts every request as answered, refused (an error reply, an
// HTTP error status, a connection refused or closed by the limits) or unanswered (no reply
// within the timeout), with latencies; samples the service's resident memory from /proc.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/display_service.hpp"
#include "serve/listen_address.hpp"

namespace lfd::serve {

struct LoadBenchOptions {
  ListenAddress address;
  int clients = 32;
  double seconds = 20;
  std::vector<std::uint8_t> quilt_png;  // shown over HoloPlay
  std::string quilt_file;               // cast over Bridge (an absolute path)
  QuiltSettings quilt;
  int timeout_ms = 10000;
};

struct RequestKindStats {
  std::string kind;
  long sent = 0, answered = 0, refused = 0, unanswered = 0;
  bool expects_answer = true;  // false: connections that vanish, counted as sent only
  std::vector<double> latency_ms;  // of answered requests
};

struct LoadBenchResult {
  std::vector<RequestKindStats> kinds;
  int service_pid = 0;
  long rss_start_kb = 0, rss_peak_first_half_kb = 0, rss_peak_second_half_kb = 0, rss_end_kb = 0;
  bool service_alive_after = false;
  double seconds = 0;
  int clients = 0;
  long unanswered() const;
};

// Throws InputError when no lfd serve answers at the address.
LoadBenchResult run_load_bench(const LoadBenchOptions& options);

std::string load_bench_table(const LoadBenchResult& result);
nlohmann::json load_bench_json(const LoadBenchResult& result);

}  // namespace lfd::serve
