#pragma once
// `lfd bench serve` (docs/serve.md, "Load"): many clients at once against a running lfd serve on
// loopback for a fixed time: HoloPlay info and quilt shows over NNG's WebSocket REQ socket (the
// framing holoplay-core speaks), Bridge calls and casts over HTTP, event sockets, and clients
// that vanish mid-connection. Counts every request as answered, busy (HoloPlay's error 6, HTTP
// 503: the service's memory budget or decoders were in use, answered at once), refused (another
// error reply, an HTTP error status, a connection refused or closed by the limits) or unanswered
// (no reply within the timeout), with latencies; samples the service's resident memory from /proc.
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
  std::string quilt_description;  // "Go: 11x6 tiles of 372x662 (4092x3972), 2.1 MiB PNG"
  int timeout_ms = 10000;
};

struct RequestKindStats {
  std::string kind;
  long sent = 0, answered = 0, busy = 0, refused = 0, unanswered = 0;
  bool expects_answer = true;  // false: connections that vanish, counted as sent only
  std::vector<double> latency_ms;  // of answered requests
  std::vector<double> busy_latency_ms;  // of busy answers
};

struct LoadBenchResult {
  std::vector<RequestKindStats> kinds;
  int service_pid = 0;
  long rss_start_kb = 0, rss_peak_first_half_kb = 0, rss_peak_second_half_kb = 0, rss_end_kb = 0;
  std::string quilt;  // what was shown, in words
  bool service_alive_after = false;
  double seconds = 0;
  int clients = 0;
  long unanswered() const;
};

// Throws InputError when no lfd serve answers at the address.
LoadBenchResult run_load_bench(const LoadBenchOptions& options);

// The quilts of real units' content for --quilt-size (docs/serve.md, "Load"; the quilt table of
// ../shared/reference/looking-glass.md): go, portrait, 16in, 32in.
struct QuiltSizePreset {
  std::string name, unit;
  int cols, rows, tile_width, tile_height;
  double aspect;
};
const std::vector<QuiltSizePreset>& quilt_size_presets();
// The preset of that name; InputError listing them for another.
const QuiltSizePreset& quilt_size_preset(const std::string& name);

std::string load_bench_table(const LoadBenchResult& result);
nlohmann::json load_bench_json(const LoadBenchResult& result);

}  // namespace lfd::serve
