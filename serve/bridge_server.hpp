#pragma once
// Bridge's HTTP API on cpp-httplib, http://host:33334/<endpoint> (docs/serve.md): PUT with a
// JSON body to BridgeApi; GET / answers that the service runs (bridge.js's status check);
// OPTIONS answers CORS preflights for allowed origins. Every request first passes the Origin
// allow-list and, on a loopback listener, the Host check: a refused one gets 403 and reaches no
// handler. Bodies, timeouts and connections are bounded (ServeLimits); a body the memory budget
// cannot take now is answered 503 with Retry-After before it is read.
#include <atomic>
#include <memory>
#include <thread>

#include "serve/bridge_api.hpp"
#include "serve/console_routes.hpp"
#include "serve/listen_address.hpp"
#include "serve/memory_budget.hpp"
#include "serve/origin_policy.hpp"

namespace httplib {
class Server;
}

namespace lfd::serve {

class BridgeServer {
 public:
  BridgeServer(BridgeApi& api, const OriginPolicy& origins, MemoryBudget& budget, const ServeLimits& limits);
  ~BridgeServer();
  void start(const ListenAddress& address);  // throws std::runtime_error naming the address
  void stop();
  std::size_t refused_requests() const { return refused_; }
  // The console's page and routes (docs/console.md), before start(); its uploads may be larger
  // than a Bridge body, up to `max_upload_bytes`.
  void set_console(ConsoleRoutes* console, std::size_t max_upload_bytes) {
    console_ = console;
    max_upload_bytes_ = max_upload_bytes;
  }

 private:
  void add_routes();

  BridgeApi& api_;
  const OriginPolicy& origins_;
  MemoryBudget& budget_;
  const ServeLimits& limits_;
  bool check_host_ = true;
  std::unique_ptr<httplib::Server> server_;
  std::thread thread_;
  std::atomic<std::size_t> refused_{0};
  ConsoleRoutes* console_ = nullptr;
  std::size_t max_upload_bytes_ = 0;
};

}  // namespace lfd::serve
