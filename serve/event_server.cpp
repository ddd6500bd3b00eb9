// Bridge's event WebSocket on NNG streams (docs/serve.md, "Events").
#include "serve/event_server.hpp"

#include "serve/peer_address.hpp"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace lfd::serve {

namespace {
constexpr std::size_t kMaxQueuedEvents = 256;
}

// One client: a reader (an aio that re-arms itself, so a closed socket is seen) and a writer
// thread draining the queue.
struct EventServer::Connection {
  nng_stream* stream = nullptr;
  nng_aio* recv_aio = nullptr;
  std::array<char, 4096> buffer{};
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<std::pair<std::string, MemoryBudget::Reservation>> queue;
  MemoryBudget* budget = nullptr;
  std::condition_variable* reap_wake = nullptr;  // the server's reaper, told when this closes
  bool closed = false;
  std::thread writer;
  int timeout_ms = 10000;

  void close() {
    {
      std::lock_guard lock(mutex);
      closed = true;
    }
    wake.notify_all();
    nng_stream_close(stream);
    if (reap_wake) reap_wake->notify_one();
  }
  void push(const std::string& text) {
    {
      std::lock_guard lock(mutex);
      if (closed) return;
      if (queue.size() >= kMaxQueuedEvents) queue.pop_front();  // a slow reader loses the oldest
      auto held = budget->try_reserve(text.size());
      if (!held && !queue.empty()) {  // the budget is full: this reader loses its oldest too
        queue.pop_front();
        held = budget->try_reserve(text.size());
      }
      if (!held) return;
      queue.emplace_back(text, std::move(held));
    }
    wake.notify_one();
  }
  void arm_recv() {
    nng_iov iov{buffer.data(), buffer.size()};
    nng_aio_set_iov(recv_aio, 1, &iov);
    nng_stream_recv(stream, recv_aio);
  }
  static void on_recv(void* arg) {
    auto* c = static_cast<Connection*>(arg);
    if (nng_aio_result(c->recv_aio) != 0) return c->close();
    c->arm_recv();  // the content (the subscription) needs no answer: every event goes to all
  }
  void write_loop() {
    nng_aio* aio = nullptr;
    if (nng_aio_alloc(&aio, nullptr, nullptr) != 0) return close();
    nng_aio_set_timeout(aio, timeout_ms);
    for (;;) {
      std::string text;
      {
        std::unique_lock lock(mutex);
        wake.wait(lock, [&] { return closed || !queue.empty(); });
        if (closed) break;
        text = std::move(queue.front().first);
        queue.pop_front();
      }
      nng_iov iov{text.data(), text.size()};
      nng_aio_set_iov(aio, 1, &iov);
      nng_stream_send(stream, aio);
      nng_aio_wait(aio);
      if (nng_aio_result(aio) != 0) {
        close();
        break;
      }
    }
    nng_aio_free(aio);
  }
  ~Connection() {
    if (recv_aio) {
      nng_aio_stop(recv_aio);
      nng_aio_free(recv_aio);
    }
    if (writer.joinable()) writer.join();
    if (stream) nng_stream_free(stream);
  }
};

EventServer::EventServer(EventHub& hub, const OriginPolicy& origins, MemoryBudget& budget, const ServeLimits& limits)
    : hub_(hub), origins_(origins), budget_(budget), limits_(limits) {}

EventServer::~EventServer() { stop(); }

void EventServer::start(const ListenAddress& address) {
  const std::string url = fmt::format("ws://{}:{}/event_source", address.ws_host(), address.events_port);
  const auto check = [&](int rv) {
    if (rv != 0) throw std::runtime_error(fmt::format("{}: {}", url, nng_strerror(rv)));
  };
  check(nng_stream_listener_alloc(&listener_, url.c_str()));
  check(nng_stream_listener_set_bool(listener_, NNG_OPT_WS_SEND_TEXT, true));
  check(nng_stream_listener_set_bool(listener_, NNG_OPT_WS_RECV_TEXT, true));
  check(nng_stream_listener_set_size(listener_, NNG_OPT_WS_RECVMAXFRAME, limits_.max_event_message_bytes));
  check(nng_stream_listener_set_size(listener_, NNG_OPT_RECVMAXSZ, limits_.max_event_message_bytes));
  check(nng_stream_listener_listen(listener_));
  check(nng_aio_alloc(&accept_aio_, &EventServer::on_accept, this));
  hub_id_ = hub_.subscribe([this](const std::string& text) {
    std::lock_guard lock(mutex_);
    for (auto& c : connections_) c->push(text);
  });
  reaper_ = std::thread([this] { reap_loop(); });
  accept_next();
}

void EventServer::reap_loop() {
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      reap_wake_.wait_for(lock, std::chrono::milliseconds(500));
      if (stopping_) return;
    }
    reap_closed();
  }
}

void EventServer::accept_next() {
  if (!stopping_) nng_stream_listener_accept(listener_, accept_aio_);
}

void EventServer::reap_closed() {
  std::list<std::shared_ptr<Connection>> closed;
  {
    std::lock_guard lock(mutex_);
    for (auto it = connections_.begin(); it != connections_.end();) {
      bool is_closed;
      {
        std::lock_guard c((*it)->mutex);
        is_closed = (*it)->closed;
      }
      if (is_closed) closed.splice(closed.end(), connections_, it++);
      else ++it;
    }
  }
}  // `closed` joins its writers here, outside the lock

void EventServer::on_accept(void* arg) {
  auto* self = static_cast<EventServer*>(arg);
  if (nng_aio_result(self->accept_aio_) != 0) {
    if (!self->stopping_) self->accept_next();
    return;
  }
  auto* stream = static_cast<nng_stream*>(nng_aio_get_output(self->accept_aio_, 0));
  const auto header = [stream](const char* name) {
    char* raw = nullptr;
    std::string value;
    if (nng_stream_get_string(stream, (std::string(NNG_OPT_WS_REQUEST_HEADER) + name).c_str(), &raw) == 0 && raw) {
      value = raw;
      nng_strfree(raw);
    }
    return value;
  };
  const std::string origin = header("Origin");
  nng_sockaddr peer{};
  const bool from_this_machine = nng_stream_get_addr(stream, NNG_OPT_REMADDR, &peer) == 0 &&
                                 OriginPolicy::from_this_machine(peer_address_text(peer), header("Host"));
  const bool over = self->connections() >= self->limits_.max_connections;
  // The console page (another port of the same host) is let in; beyond loopback with its token.
  if (!self->origins_.allows(origin, header("Host")) || !self->origins_.token_ok(from_this_machine, header("Cookie"), header("Authorization")) ||
      over) {
    ++self->refused_;
    spdlog::warn("events: refused a connection ({})",
                 over ? "over the connection limit" : "origin " + origin.substr(0, 200));
    nng_stream_close(stream);
    nng_stream_free(stream);
    return self->accept_next();
  }
  auto c = std::make_shared<Connection>();
  c->stream = stream;
  c->timeout_ms = self->limits_.io_timeout_s * 1000;
  c->budget = &self->budget_;
  c->reap_wake = &self->reap_wake_;
  if (nng_aio_alloc(&c->recv_aio, &Connection::on_recv, c.get()) != 0) return self->accept_next();
  c->writer = std::thread([raw = c.get()] { raw->write_loop(); });
  c->arm_recv();
  {
    std::lock_guard lock(self->mutex_);
    self->connections_.push_back(std::move(c));
  }
  self->accept_next();
}

int EventServer::connections() const {
  std::lock_guard lock(mutex_);
  int open = 0;
  for (const auto& c : connections_) {
    std::lock_guard c_lock(c->mutex);
    open += c->closed ? 0 : 1;
  }
  return open;
}

void EventServer::stop() {
  if (!listener_) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  reap_wake_.notify_all();
  if (reaper_.joinable()) reaper_.join();
  hub_.unsubscribe(hub_id_);
  nng_stream_listener_close(listener_);
  nng_aio_stop(accept_aio_);
  nng_aio_free(accept_aio_);
  std::list<std::shared_ptr<Connection>> all;
  {
    std::lock_guard lock(mutex_);
    all.swap(connections_);
  }
  for (auto& c : all) c->close();
  all.clear();
  nng_stream_listener_free(listener_);
  listener_ = nullptr;
}

}  // namespace lfd::serve
