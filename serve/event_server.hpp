#pragma once
// Bridge's event WebSocket, ws://host:9724/event_source (docs/serve.md, "Events"): plain
// WebSocket text messages (bridge.js opens it with `new WebSocket(url)`, sends
// `{"subscribe_orchestration_events": token}` and dispatches on payload.value.event.value).
// Built on NNG's WebSocket stream API (the same library as the HoloPlay endpoint, so the service
// has one WebSocket implementation). A refused Origin or a connection over the limit is closed at
// once; each connection keeps a queue bounded in count and in bytes (the memory budget: an event
// that does not fit is dropped for that connection), and one that does not take its messages
// within the timeout is dropped.
#include <atomic>
#include <condition_variable>
#include <list>
#include <memory>
#include <mutex>
#include <thread>

#include <nng/nng.h>

#include "serve/event_hub.hpp"
#include "serve/listen_address.hpp"
#include "serve/memory_budget.hpp"
#include "serve/origin_policy.hpp"
#include "serve/serve_limits.hpp"

namespace lfd::serve {

class EventServer {
 public:
  EventServer(EventHub& hub, const OriginPolicy& origins, MemoryBudget& budget, const ServeLimits& limits);
  ~EventServer();
  void start(const ListenAddress& address);  // throws std::runtime_error naming the URL
  void stop();
  int connections() const;  // open ones (a closed one waits for the reaper a moment)
  std::size_t refused_connections() const { return refused_; }

  struct Connection;

 private:
  static void on_accept(void* self);
  void accept_next();
  // Closed connections are freed on the reaper's thread, never on NNG's: freeing one waits for
  // its writer (up to the write timeout), which on NNG's callback thread held up every accept.
  void reap_loop();
  void reap_closed();

  EventHub& hub_;
  const OriginPolicy& origins_;
  MemoryBudget& budget_;
  const ServeLimits& limits_;
  nng_stream_listener* listener_ = nullptr;
  nng_aio* accept_aio_ = nullptr;
  int hub_id_ = 0;
  mutable std::mutex mutex_;
  std::list<std::shared_ptr<Connection>> connections_;
  std::atomic<bool> stopping_{false};
  std::condition_variable reap_wake_;
  std::thread reaper_;
  std::atomic<std::size_t> refused_{0};
};

}  // namespace lfd::serve
