#pragma once
// The HoloPlay Service endpoint, ws://host:11222/driver (docs/serve.md): a WebSocket listener
// (Boost.Beast) speaking the nanomsg SP-over-WebSocket framing that holoplay-core uses
// (subprotocol rep.sp.nanomsg.org; each message starts with the 4-byte request id, echoed
// before the reply). A handshake whose Origin the policy refuses, without the access token
// beyond loopback, or over the connection limit is refused before any message is read, and so
// is one to a loopback listener whose Host header is not a loopback name (DNS rebinding).
//
// Why not NNG's REP socket (docs/serve.md, "Memory"): NNG reads every connection's message whole
// (then copies it) before the service sees it, so 64 clients sending quilts at once held up to
// 64 x 2 x a quilt that no budget could refuse. Here a message is read in chunks of 64 KiB, and
// the service decides before it keeps the rest:
// - up to kSmallRequestBytes it is read whole and parsed to see whether it carries content;
// - a request without content (info, uniforms, check, a cached show) goes to its own lane of
//   workers and answers in milliseconds whatever the large ones do;
// - one with content is admitted only while a content worker is free and the memory budget
//   holds three times its size (known from the frame header); otherwise its bytes are read and
//   dropped chunk by chunk and it is answered busy at once.
// So what a connection holds while it is read is one chunk unless its content was admitted.
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

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

  // Requests up to this size are read whole and parsed on arrival to see whether they carry
  // content; larger ones always do.
  static constexpr std::size_t kSmallRequestBytes = 64u << 10;
  static constexpr std::size_t kChunkBytes = 64u << 10;

 private:
  struct Connection;
  struct Listener;
  void accept_loop(Listener& listener);
  void serve(const std::shared_ptr<Connection>& c);  // holoplay_connection.cpp
  // Has `message` (its body from body_offset) handled by a lane's worker and waits for the reply;
  // empty when the service stops first.
  std::vector<std::uint8_t> handle_in_lane(BoundedTaskQueue& lane, std::vector<std::uint8_t> message,
                                           std::size_t body_offset, MemoryBudget::Reservation held);
  void watch_deadlines();

  HoloPlayProtocol& protocol_;
  const OriginPolicy& origins_;
  const ServeLimits& limits_;
  std::unique_ptr<Listener> listener_;  // the io_context and acceptor, and the count of open connections
  std::unique_ptr<BoundedTaskQueue> small_lane_, content_lane_;
  std::mutex connections_mutex_;
  std::vector<std::shared_ptr<Connection>> connections_;
  std::thread accept_thread_, watchdog_;
  std::atomic<int> content_in_flight_{0};
  bool check_host_ = false;  // a loopback listener: the Host header names a loopback host
  std::atomic<bool> stopping_{false};
  std::atomic<std::size_t> refused_{0};
  std::atomic<std::size_t> answered_{0};
};

}  // namespace lfd::serve
