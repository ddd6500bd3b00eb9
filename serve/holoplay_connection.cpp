// One HoloPlay connection: the WebSocket handshake and its checks, then each request read in
// chunks and admitted before its content is kept (serve/holoplay_server.hpp; docs/serve.md,
// "Memory").
#include "serve/holoplay_connection.hpp"

#include <array>
#include <string>
#include <string_view>

#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <spdlog/spdlog.h>

namespace lfd::serve {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

namespace {

constexpr std::string_view kSubprotocol = "rep.sp.nanomsg.org";
constexpr std::size_t kHandshakeBytes = 16u << 10;
constexpr std::size_t kMaxHeaderBytes = 32;  // 8 words of SP header

std::string_view text(beast::string_view s) { return {s.data(), s.size()}; }

// Whether a Sec-WebSocket-Protocol header ("a, b, c") offers the REP peer's protocol.
bool offers_subprotocol(std::string_view header) {
  while (!header.empty()) {
    const auto comma = header.find(',');
    std::string_view token = header.substr(0, comma);
    while (!token.empty() && token.front() == ' ') token.remove_prefix(1);
    while (!token.empty() && token.back() == ' ') token.remove_suffix(1);
    if (token == kSubprotocol) return true;
    if (comma == std::string_view::npos) break;
    header.remove_prefix(comma + 1);
  }
  return false;
}

}  // namespace

void HoloPlayServer::serve(const std::shared_ptr<Connection>& c) {
  beast::error_code ec;
  c->expire_after(limits_.io_timeout_s);
  beast::flat_buffer handshake(kHandshakeBytes);
  http::request_parser<http::empty_body> parser;
  parser.header_limit(kHandshakeBytes);
  http::read(c->socket, handshake, parser, ec);
  if (ec) return;
  const auto& request = parser.get();
  const auto refuse = [&](http::status status, std::string_view why) {
    http::response<http::string_body> reply{status, request.version()};
    reply.set(http::field::connection, "close");
    reply.body() = std::string(why);
    reply.prepare_payload();
    http::write(c->socket, reply, ec);
  };
  if (!websocket::is_upgrade(request) || request.target() != "/driver")
    return refuse(http::status::not_found, "the HoloPlay Service protocol is a WebSocket at /driver");
  if (!offers_subprotocol(text(request[http::field::sec_websocket_protocol])))
    return refuse(http::status::bad_request, "the HoloPlay Service protocol needs subprotocol rep.sp.nanomsg.org");
  if (check_host_ && !OriginPolicy::is_loopback_host(text(request[http::field::host]))) {
    ++refused_;
    return refuse(http::status::forbidden, "refused: the Host header names no loopback host");
  }
  const std::string_view origin = text(request[http::field::origin]);
  const std::string peer = c->socket.remote_endpoint(ec).address().to_string();
  const bool from_here = !ec && OriginPolicy::from_this_machine(peer, text(request[http::field::host]));
  if (!origins_.allows(origin) ||
      !origins_.token_ok(from_here, text(request[http::field::cookie]), text(request[http::field::authorization]))) {
    ++refused_;
    spdlog::warn("holoplay: refused a connection from origin {}", std::string(origin.substr(0, 200)));
    return refuse(http::status::forbidden, "refused: origin or access token");
  }
  websocket::stream<asio::ip::tcp::socket&> ws(c->socket);
  ws.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& reply) { reply.set(http::field::sec_websocket_protocol, std::string(kSubprotocol)); }));
  ws.read_message_max(limits_.max_message_bytes + kMaxHeaderBytes);
  ws.auto_fragment(false);
  ws.binary(true);
  ws.accept(request, ec);
  if (ec) return;

  std::vector<std::uint8_t> chunk(kChunkBytes);
  const auto read_chunk = [&]() -> std::size_t { return ws.read_some(asio::buffer(chunk), ec); };
  while (!stopping_) {
    c->no_deadline();  // idle until the next request begins
    std::size_t n = read_chunk();
    if (ec) return;
    c->expire_after(limits_.io_timeout_s);
    // A small request is read whole and parsed for content; a larger one carries content.
    std::vector<std::uint8_t> message(chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
    while (!ws.is_message_done() && message.size() <= kSmallRequestBytes + kMaxHeaderBytes) {
      n = read_chunk();
      if (ec) return;
      message.insert(message.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
    }
    const auto header = sp_header_length(message);
    if (!header) return;  // not the SP framing: closed, as NNG does
    const std::vector<std::uint8_t> id(message.begin(), message.begin() + static_cast<std::ptrdiff_t>(*header));
    const bool content =
        !ws.is_message_done() ||
        protocol_.carries_content(std::span(message).subspan(*header), kSmallRequestBytes);
    // Content: a free content worker and the budget for the message's copies (its whole size
    // from the frame header), or its bytes dropped as they arrive and a busy answer.
    MemoryBudget::Reservation held;
    bool admitted = !content;
    if (content) {
      const std::size_t expected = message.size() + (ws.is_message_done() ? 0 : ws.read_size_hint(1));
      if (++content_in_flight_ <= limits_.worker_threads) held = protocol_.admit(expected);
      admitted = static_cast<bool>(held);
      if (admitted) message.reserve(expected);
      else --content_in_flight_;
    }
    while (!ws.is_message_done()) {
      n = read_chunk();
      if (ec) {
        if (content && admitted) --content_in_flight_;
        return;
      }
      if (!admitted) continue;  // dropped chunk by chunk
      if (message.size() + n > message.capacity()) {  // more frames than the first announced
        auto more = protocol_.admit(message.capacity());
        if (!more) {  // the rest of this one is dropped too
          admitted = false;
          held.release();
          message = {};
          --content_in_flight_;
          continue;
        }
        held.merge(std::move(more));
        message.reserve(2 * message.capacity());
      }
      message.insert(message.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
    }
    std::vector<std::uint8_t> reply;
    if (!admitted) {
      reply = HoloPlayProtocol::busy_reply("busy: the service is handling as much content as it holds; try again");
    } else {
      // The service's own work (a decode behind others) is not held to the client's deadline.
      c->no_deadline();
      reply = handle_in_lane(content ? *content_lane_ : *small_lane_, std::move(message), *header, std::move(held));
      if (content) --content_in_flight_;
      if (reply.empty()) return;  // stopping
      c->expire_after(limits_.io_timeout_s);
    }
    const std::array<asio::const_buffer, 2> out{asio::buffer(id), asio::buffer(reply)};
    ws.write(out, ec);
    if (ec) return;
    ++answered_;
  }
}

}  // namespace lfd::serve
