#pragma once
// The HoloPlay Service endpoint, ws://host:11222/driver (docs/serve.md): NNG's REP socket on
// its WebSocket transport, which speaks the nanomsg SP-over-WebSocket framing (subprotocol
// rep.sp.nanomsg.org, the 4-byte request id) that holoplay-core uses. Worker contexts answer
// requests at once; a connection whose Origin the policy refuses, or one over the connection
// limit, is closed before any of its messages is read.
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

#include <nng/nng.h>

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

 private:
  static void on_pipe(nng_pipe pipe, nng_pipe_ev event, void* self);
  void work();

  HoloPlayProtocol& protocol_;
  const OriginPolicy& origins_;
  const ServeLimits& limits_;
  nng_socket socket_ = NNG_SOCKET_INITIALIZER;
  bool open_ = false;
  std::vector<std::thread> workers_;
  std::atomic<int> connections_{0};
  std::atomic<std::size_t> refused_{0};
  std::atomic<std::size_t> answered_{0};
};

}  // namespace lfd::serve
