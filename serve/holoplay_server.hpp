#pragma once
// The HoloPlay Service endpoint, ws://host:11222/driver (docs/serve.md): NNG's REP socket on
// its WebSocket transport, which speaks the nanomsg SP-over-WebSocket framing (subprotocol
// rep.sp.nanomsg.org, the 4-byte request id) that holoplay-core uses. A connection whose Origin
// the policy refuses, or one over the connection limit, is closed before any of its messages is
// read.
//
// Admission (docs/serve.md, "Memory" and "Fair under load"): one asynchronous REP context per
// allowed connection takes every request as it arrives, so nothing waits unseen in NNG's
// queues. Requests without content (info, uniforms, check, a cached show) go to their own lane of workers
// and answer in milliseconds whatever the large ones do; a request carrying content (a quilt)
// is admitted only while a content worker is free and the memory budget holds three times its
// size, and is otherwise answered busy at once, its bytes freed.
#include <atomic>
#include <memory>
#include <vector>

#include <nng/nng.h>

#include "serve/bounded_task_queue.hpp"
#include "serve/holoplay_protocol.hpp"
#include "serve/listen_address.hpp"
#include "serve/origin_policy.hpp"

namespace lfd::serve {

class HoloPlayServer {
 public:
  HoloPlayServer(HoloPlayProtocol& protocol, const OriginPolicy& origins, const ServeLimits& limits);
  ~HoloPlayServer();
  void start(const ListenAddress& address);  // throws std::runtime_error naming the URL
  void stop();
  std::size_t refused_connections() const { return refused_; }
  std::size_t answered() const { return answered_; }

  // Requests up to this size are parsed on arrival to see whether they carry content; larger
  // ones always do.
  static constexpr std::size_t kSmallRequestBytes = 64u << 10;

 private:
  struct Context;
  static void on_pipe(nng_pipe pipe, nng_pipe_ev event, void* self);
  static void on_context_event(void* context);
  void received(Context& c);
  void answer(Context& c, nng_msg* request, std::vector<std::uint8_t> reply);
  void handle_in_lane(Context& c, nng_msg* request, MemoryBudget::Reservation held, bool content);

  HoloPlayProtocol& protocol_;
  const OriginPolicy& origins_;
  const ServeLimits& limits_;
  nng_socket socket_ = NNG_SOCKET_INITIALIZER;
  bool open_ = false;
  std::vector<std::unique_ptr<Context>> contexts_;
  std::unique_ptr<BoundedTaskQueue> small_lane_, content_lane_;
  std::atomic<int> content_in_flight_{0};
  std::atomic<bool> stopping_{false};
  std::atomic<int> connections_{0};
  std::atomic<std::size_t> refused_{0};
  std::atomic<std::size_t> answered_{0};
};

}  // namespace lfd::serve
