// The HoloPlay Service endpoint: its listener, connection limit, deadlines and stop
// (docs/serve.md, "HoloPlay Service protocol"); one connection's reading and admission is
// holoplay_connection.cpp.
#include "serve/holoplay_server.hpp"

#include <sys/socket.h>

#include <chrono>
#include <condition_variable>
#include <future>
#include <stdexcept>
#include <string>

#include <boost/asio/ip/tcp.hpp>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "serve/holoplay_connection.hpp"

namespace lfd::serve {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

struct HoloPlayServer::Listener {
  asio::io_context io;
  tcp::acceptor acceptor{io};
  std::mutex mutex;
  std::condition_variable all_closed;
  int open_connections = 0;
};

HoloPlayServer::HoloPlayServer(HoloPlayProtocol& protocol, const OriginPolicy& origins, const ServeLimits& limits)
    : protocol_(protocol), origins_(origins), limits_(limits) {}

HoloPlayServer::~HoloPlayServer() { stop(); }

void HoloPlayServer::start(const ListenAddress& address) {
  const std::string url = fmt::format("ws://{}:{}/driver", address.url_host(), address.holoplay_port);
  listener_ = std::make_unique<Listener>();
  stopping_ = false;
  check_host_ = address.is_loopback();
  try {
    tcp::resolver resolver(listener_->io);
    const tcp::endpoint endpoint = *resolver.resolve(address.host, std::to_string(address.holoplay_port)).begin();
    auto& acceptor = listener_->acceptor;
    acceptor.open(endpoint.protocol());
    acceptor.set_option(tcp::acceptor::reuse_address(true));
    acceptor.bind(endpoint);
    acceptor.listen(128);
  } catch (const std::exception& e) {
    listener_.reset();
    throw std::runtime_error(fmt::format("{}: {}", url, e.what()));
  }
  small_lane_ = std::make_unique<BoundedTaskQueue>(2, limits_.max_connections);
  content_lane_ = std::make_unique<BoundedTaskQueue>(limits_.worker_threads, limits_.max_connections);
  accept_thread_ = std::thread([this] { accept_loop(*listener_); });
  watchdog_ = std::thread([this] { watch_deadlines(); });
}

void HoloPlayServer::accept_loop(Listener& listener) {
  while (!stopping_) {
    tcp::socket socket(listener.io);
    boost::system::error_code ec;
    listener.acceptor.accept(socket, ec);
    if (stopping_) break;
    if (ec) {  // out of descriptors, a connection reset before it was taken: go on
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    auto c = std::make_shared<Connection>(std::move(socket));
    {
      std::lock_guard lock(connections_mutex_);
      if (static_cast<int>(connections_.size()) >= limits_.max_connections) {
        ++refused_;
        spdlog::warn("holoplay: refused a connection over the limit of {}", limits_.max_connections);
        continue;  // closed as `c` goes
      }
      connections_.push_back(c);
    }
    {
      std::lock_guard lock(listener.mutex);
      ++listener.open_connections;
    }
    std::thread([this, c, &listener] {
      serve(c);
      {
        // Out of the list before the socket closes, so the watchdog never cuts a reused descriptor.
        std::lock_guard lock(connections_mutex_);
        std::erase(connections_, c);
        c->closed = true;
      }
      std::lock_guard lock(listener.mutex);
      if (--listener.open_connections == 0) listener.all_closed.notify_all();
    }).detach();
  }
}

// A connection past its deadline (a handshake, a message or a reply taking longer than
// io_timeout_s) is cut: its thread's blocked read or write returns.
void HoloPlayServer::watch_deadlines() {
  while (!stopping_) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    std::lock_guard lock(connections_mutex_);
    for (auto& c : connections_)
      if (c->past_deadline()) c->cut();
  }
}

std::vector<std::uint8_t> HoloPlayServer::handle_in_lane(BoundedTaskQueue& lane, std::vector<std::uint8_t> message,
                                                          std::size_t body_offset, MemoryBudget::Reservation held) {
  auto job = std::make_shared<std::packaged_task<std::vector<std::uint8_t>()>>(
      [this, message = std::move(message), body_offset, held = std::move(held)]() mutable {
        if (stopping_) return HoloPlayProtocol::busy_reply("busy: the service is stopping");
        const std::span<const std::uint8_t> payload(message.data() + body_offset, message.size() - body_offset);
        return protocol_.handle(payload, std::move(held));
      });
  auto reply = job->get_future();
  lane.enqueue([job] { (*job)(); });
  while (reply.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready)
    if (stopping_) return {};  // abandoned: the service is going
  return reply.get();
}

void HoloPlayServer::stop() {
  if (!listener_ || stopping_.exchange(true)) return;
  ::shutdown(listener_->acceptor.native_handle(), SHUT_RDWR);  // ends the blocked accept
  if (accept_thread_.joinable()) accept_thread_.join();
  if (watchdog_.joinable()) watchdog_.join();
  {
    std::lock_guard lock(connections_mutex_);
    for (auto& c : connections_) c->cut();
  }
  {
    std::unique_lock lock(listener_->mutex);
    listener_->all_closed.wait(lock, [this] { return listener_->open_connections == 0; });
  }
  small_lane_->shutdown();
  content_lane_->shutdown();
  boost::system::error_code ec;
  listener_->acceptor.close(ec);
}

}  // namespace lfd::serve
