#pragma once
// One HoloPlay connection (serve/holoplay_server.hpp): its socket and the deadline the
// watchdog holds it to.
#include <sys/socket.h>

#include <atomic>
#include <chrono>
#include <cstdint>

#include <boost/asio/ip/tcp.hpp>

#include "serve/holoplay_server.hpp"
#include "serve/sp_header.hpp"

namespace lfd::serve {

struct HoloPlayServer::Connection {
  explicit Connection(boost::asio::ip::tcp::socket s) : socket(std::move(s)) {}
  boost::asio::ip::tcp::socket socket;
  bool closed = false;  // set under the server's connections mutex before the socket closes

  // A deadline while a handshake, a message or a reply is on the wire; none while idle between
  // requests (holoplay-core keeps its connection for the app's life) or while the service
  // handles one (a decode may wait behind others).
  void expire_after(int seconds) {
    deadline_ms_ = now_ms() + std::int64_t{seconds} * 1000;
  }
  void no_deadline() { deadline_ms_ = 0; }
  bool past_deadline() const {
    const std::int64_t d = deadline_ms_;
    return d != 0 && now_ms() > d;
  }
  // Ends the connection's blocked read or write from another thread (the descriptor stays
  // open until its own thread lets it go).
  void cut() {
    if (!closed) ::shutdown(socket.native_handle(), SHUT_RDWR);
  }

 private:
  static std::int64_t now_ms() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  std::atomic<std::int64_t> deadline_ms_{0};
};

}  // namespace lfd::serve
