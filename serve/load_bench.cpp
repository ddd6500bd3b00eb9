// The load test of lfd serve (docs/serve.md, "Load").
#include "serve/load_bench.hpp"

#include <signal.h>
#include <sys/socket.h>
#include <netinet/in.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <httplib.h>
#include <nng/nng.h>
#include <nng/protocol/reqrep0/req.h>

#include "serve/cbor_json.hpp"
#include "serve/memory_budget.hpp"
#include "serve/status_client.hpp"
#include "util/error.hpp"

namespace lfd::serve {

namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;
enum class Outcome { kAnswered, kBusy, kRefused, kUnanswered };
constexpr int kHoloPlayBusy = 6;  // HoloPlayError::kBusy

long rss_kb(int pid) { return static_cast<long>(resident_bytes(pid) / 1024); }

// A HoloPlay client: one REQ socket over WebSocket for the client's whole run, as holoplay-core
// keeps its connection (closing an NNG socket per request hung NNG 1.5.2's client under this
// load; the service's connection churn comes from the event sockets and vanishing clients).
struct HoloPlayClient {
  nng_socket socket{};
  explicit HoloPlayClient(const LoadBenchOptions& o) {
    nng_req0_open(&socket);
    nng_socket_set_ms(socket, NNG_OPT_RECVTIMEO, o.timeout_ms);
    nng_socket_set_ms(socket, NNG_OPT_SENDTIMEO, o.timeout_ms);
    nng_socket_set_ms(socket, NNG_OPT_REQ_RESENDTIME, 0);
    const std::string url = fmt::format("ws://{}:{}/driver", o.address.ws_host(), o.address.holoplay_port);
    nng_dial(socket, url.c_str(), nullptr, NNG_FLAG_NONBLOCK);
  }
  ~HoloPlayClient() { nng_close(socket); }

  Outcome request(const json& request) {
    const auto bytes = encode_cbor(request);
    nng_msg* m = nullptr;
    nng_msg_alloc(&m, 0);
    nng_msg_append(m, bytes.data(), bytes.size());
    if (nng_sendmsg(socket, m, 0) != 0) {
      nng_msg_free(m);
      return Outcome::kUnanswered;
    }
    if (const int rv = nng_recvmsg(socket, &m, 0); rv != 0)
      return rv == NNG_ETIMEDOUT ? Outcome::kUnanswered : Outcome::kRefused;
    Outcome outcome = Outcome::kRefused;
    try {
      const json reply = decode_cbor({static_cast<const std::uint8_t*>(nng_msg_body(m)), nng_msg_len(m)}, {});
      const int error = reply.value("error", -1);
      outcome = error == 0 ? Outcome::kAnswered : error == kHoloPlayBusy ? Outcome::kBusy : Outcome::kRefused;
    } catch (const InputError&) {
    }
    nng_msg_free(m);
    return outcome;
  }
};

Outcome bridge_put(httplib::Client& c, const std::string& endpoint, const json& body, int timeout_ms) {
  const auto start = std::chrono::steady_clock::now();
  const auto r = c.Put(("/" + endpoint).c_str(), body.dump(), "application/json");
  // No answer read in time is unanswered; a connection refused or closed first is a refusal.
  // cpp-httplib reports both a read timeout and a connection the service closed (its keep-alive
  // ending as the request went out) as a read or write error: the time taken tells them apart.
  if (!r) {
    const double waited_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const bool io_error = r.error() == httplib::Error::Read || r.error() == httplib::Error::Write;
    return io_error && waited_ms >= 0.9 * timeout_ms ? Outcome::kUnanswered : Outcome::kRefused;
  }
  if (r->status == 503) return Outcome::kBusy;
  if (r->status != 200) return Outcome::kRefused;
  const json reply = json::parse(r->body, nullptr, false);
  return !reply.is_discarded() && reply["status"]["value"] == "Completion" ? Outcome::kAnswered : Outcome::kRefused;
}

// An event socket opened and closed (connect, maybe one event, leave).
Outcome event_socket(const LoadBenchOptions& o) {
  nng_stream_dialer* d = nullptr;
  const std::string url = fmt::format("ws://{}:{}/event_source", o.address.ws_host(), o.address.events_port);
  if (nng_stream_dialer_alloc(&d, url.c_str()) != 0) return Outcome::kRefused;
  nng_aio* aio = nullptr;
  nng_aio_alloc(&aio, nullptr, nullptr);
  nng_aio_set_timeout(aio, o.timeout_ms);
  nng_stream_dialer_dial(d, aio);
  nng_aio_wait(aio);
  Outcome outcome = nng_aio_result(aio) == 0 ? Outcome::kAnswered
                    : nng_aio_result(aio) == NNG_ETIMEDOUT ? Outcome::kUnanswered : Outcome::kRefused;
  if (outcome == Outcome::kAnswered) nng_stream_free(static_cast<nng_stream*>(nng_aio_get_output(aio, 0)));
  nng_aio_free(aio);
  nng_stream_dialer_free(d);
  return outcome;
}

// A client that vanishes: half a WebSocket handshake, then gone. Nothing to answer.
void vanish(const LoadBenchOptions& o) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  const timeval two_seconds{2, 0};  // bounds connect() too (Linux)
  ::setsockopt(s, SOL_SOCKET, SO_SNDTIMEO, &two_seconds, sizeof two_seconds);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(o.address.holoplay_port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) {
    const char partial[] = "GET /driver HTTP/1.1\r\nHost: localhost\r\nUpgrade: webso";
    [[maybe_unused]] auto n = ::send(s, partial, sizeof partial - 1, MSG_NOSIGNAL);
  }
  ::close(s);
}

struct Shared {
  std::mutex mutex;
  std::vector<RequestKindStats> kinds;
  void add(std::size_t kind, Outcome outcome, double ms) {
    std::lock_guard lock(mutex);
    RequestKindStats& k = kinds[kind];
    ++k.sent;
    if (!k.expects_answer) return;
    if (outcome == Outcome::kAnswered) {
      ++k.answered;
      k.latency_ms.push_back(ms);
    } else if (outcome == Outcome::kBusy) {
      ++k.busy;
      k.busy_latency_ms.push_back(ms);
    } else if (outcome == Outcome::kRefused) {
      ++k.refused;
    } else {
      ++k.unanswered;
    }
  }
};

void client_loop(const LoadBenchOptions& o, int id, Clock::time_point end, Shared& shared) {
  httplib::Client http(o.address.host, o.address.bridge_port);
  http.set_read_timeout(o.timeout_ms / 1000, 0);
  http.set_write_timeout(o.timeout_ms / 1000, 0);
  http.set_connection_timeout(o.timeout_ms / 1000, 0);
  // 64 clients connecting at once overflow cpp-httplib's listen backlog (5): ask again, as a
  // client whose connection was refused would.
  std::string token;
  for (int attempt = 0; attempt < 50 && token.empty() && Clock::now() < end; ++attempt) {
    const auto reply = http.Put("/enter_orchestration", "{}", "application/json");
    if (reply && reply->status == 200) token = json::parse(reply->body)["payload"]["value"].get<std::string>();
    else std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const json show = {{"cmd", {{"show", {{"source", "bindata"}, {"quilt", {{"type", "image"},
                        {"settings", {{"vx", o.quilt.cols}, {"vy", o.quilt.rows}, {"aspect", o.quilt.aspect}}}}}}}}},
                     {"bin", json::binary(o.quilt_png)}};
  const std::string playlist = fmt::format("bench-{}", id);
  HoloPlayClient holoplay(o);
  for (long i = id; Clock::now() < end; ++i) {
    const std::size_t kind = static_cast<std::size_t>(i % 6);
    const auto start = Clock::now();
    Outcome outcome = Outcome::kAnswered;
    switch (kind) {
      case 0: outcome = holoplay.request({{"cmd", {{"info", json::object()}}}, {"bin", nullptr}}); break;
      case 1: outcome = holoplay.request(show); break;
      case 2: outcome = bridge_put(http, "available_output_devices", {{"orchestration", token}}, o.timeout_ms); break;
      case 3:
        outcome = bridge_put(http, "instance_playlist", {{"orchestration", token}, {"name", playlist}}, o.timeout_ms);
        if (outcome == Outcome::kAnswered)
          outcome = bridge_put(http, "insert_playlist_entry",
                               {{"orchestration", token}, {"name", playlist}, {"uri", "file://" + o.quilt_file},
                                {"rows", o.quilt.rows}, {"cols", o.quilt.cols}, {"aspect", o.quilt.aspect}},
                               o.timeout_ms);
        if (outcome == Outcome::kAnswered)
          outcome = bridge_put(http, "play_playlist", {{"orchestration", token}, {"name", playlist}, {"head_index", 0}}, o.timeout_ms);
        break;
      case 4: outcome = event_socket(o); break;
      case 5: vanish(o); break;  // counted as sent only: nothing is due
    }
    shared.add(kind, outcome, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
}

}  // namespace

long LoadBenchResult::unanswered() const {
  long n = 0;
  for (const auto& k : kinds) n += k.unanswered;
  return n;
}

LoadBenchResult run_load_bench(const LoadBenchOptions& o) {
  const json status = query_status(o.address);
  LoadBenchResult result;
  result.service_pid = status.value("pid", 0);
  if (result.service_pid <= 0) throw_input_error("the service at the address did not say its process id");
  result.clients = o.clients;
  result.quilt = o.quilt_description;
  result.seconds = o.seconds;
  Shared shared;
  for (const char* kind : {"holoplay info", "holoplay show (quilt bytes)", "bridge available_output_devices",
                           "bridge cast (3 calls)", "event socket open/close"})
    shared.kinds.push_back({kind});
  shared.kinds.push_back({"vanishing client (half a handshake)"});
  shared.kinds.back().expects_answer = false;
  result.rss_start_kb = rss_kb(result.service_pid);
  const auto start = Clock::now();
  const auto end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds));
  std::vector<std::thread> clients;
  for (int i = 0; i < o.clients; ++i) clients.emplace_back([&, i] { client_loop(o, i, end, shared); });
  while (Clock::now() < end) {
    const long rss = rss_kb(result.service_pid);
    const bool first_half = Clock::now() < start + (end - start) / 2;
    long& peak = first_half ? result.rss_peak_first_half_kb : result.rss_peak_second_half_kb;
    peak = std::max(peak, rss);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (auto& t : clients) t.join();
  result.rss_end_kb = rss_kb(result.service_pid);
  result.service_alive_after = ::kill(result.service_pid, 0) == 0;
  try {
    query_status(o.address);
  } catch (const InputError&) {
    result.service_alive_after = false;
  }
  result.kinds = std::move(shared.kinds);
  return result;
}

std::string load_bench_table(const LoadBenchResult& r) {
  std::string out = fmt::format("lfd bench serve: {} clients for {:.0f} s against lfd serve (pid {})\n", r.clients,
                                r.seconds, r.service_pid);
  if (!r.quilt.empty()) out += "quilt: " + r.quilt + "\n";
  out += fmt::format("{:<34} {:>6} {:>8} {:>6} {:>7} {:>10} {:>10} {:>9} {:>10}\n", "request", "sent", "answered",
                     "busy", "refused", "unanswered", "median ms", "p99 ms", "busy p99");
  for (const auto& k : r.kinds) {
    if (!k.expects_answer) {
      out += fmt::format("{:<34} {:>6} {:>8} {:>6} {:>7} {:>10} {:>10} {:>9} {:>10}\n", k.kind, k.sent, "-", "-", "-",
                         "-", "-", "-", "-");
      continue;
    }
    out += fmt::format("{:<34} {:>6} {:>8} {:>6} {:>7} {:>10} {:>10.2f} {:>9.2f} {:>10.2f}\n", k.kind, k.sent,
                       k.answered, k.busy, k.refused, k.unanswered, percentile(k.latency_ms, 0.5),
                       percentile(k.latency_ms, 0.99), percentile(k.busy_latency_ms, 0.99));
  }
  out += fmt::format("service RSS: start {:.1f} MiB, peak first half {:.1f} MiB, peak second half {:.1f} MiB, end {:.1f} MiB\n",
                     r.rss_start_kb / 1024.0, r.rss_peak_first_half_kb / 1024.0, r.rss_peak_second_half_kb / 1024.0,
                     r.rss_end_kb / 1024.0);
  out += fmt::format("service alive and answering after the run: {}\n", r.service_alive_after ? "yes" : "NO");
  return out;
}

nlohmann::json load_bench_json(const LoadBenchResult& r) {
  json kinds = json::array();
  for (const auto& k : r.kinds)
    kinds.push_back({{"kind", k.kind}, {"sent", k.sent}, {"answered", k.answered}, {"busy", k.busy}, {"refused", k.refused},
                     {"unanswered", k.unanswered}, {"median_ms", percentile(k.latency_ms, 0.5)},
                     {"p99_ms", percentile(k.latency_ms, 0.99)}, {"busy_p99_ms", percentile(k.busy_latency_ms, 0.99)}});
  return {{"bench", "serve"}, {"quilt", r.quilt}, {"clients", r.clients}, {"seconds", r.seconds}, {"service_pid", r.service_pid},
          {"requests", kinds}, {"rss_start_kb", r.rss_start_kb}, {"rss_peak_first_half_kb", r.rss_peak_first_half_kb},
          {"rss_peak_second_half_kb", r.rss_peak_second_half_kb}, {"rss_end_kb", r.rss_end_kb},
          {"service_alive_after", r.service_alive_after}};
}

const std::vector<QuiltSizePreset>& quilt_size_presets() {
  // Go's from its content as the vendor ships it (11x6 of 372x662); the others the standard
  // quilt of each unit (../shared/reference/looking-glass.md, "Standard quilt per device").
  static const std::vector<QuiltSizePreset> presets = {
      {"go", "Looking Glass Go", 11, 6, 372, 662, 0.5625},
      {"portrait", "Looking Glass Portrait", 8, 6, 420, 560, 0.75},
      {"16in", "16\" Landscape (Gen3)", 7, 7, 857, 857, 1.77778},
      {"32in", "32\" Landscape (Gen3)", 7, 7, 1170, 1170, 1.77778}};
  return presets;
}

const QuiltSizePreset& quilt_size_preset(const std::string& name) {
  std::string names;
  for (const auto& p : quilt_size_presets()) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw_input_error("--quilt-size: {} is not one of {}", name, names);
}

}  // namespace lfd::serve
