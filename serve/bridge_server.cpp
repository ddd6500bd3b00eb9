// Bridge's HTTP API server (docs/serve.md, "Bridge HTTP API").
#include "serve/bridge_server.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>
#include <httplib.h>
#include <spdlog/spdlog.h>

#include "serve/bounded_body.hpp"
#include "serve/bounded_task_queue.hpp"
#include "serve/bridge_reply.hpp"

namespace lfd::serve {

namespace {
// The body being read and handled on this worker thread: reserved before cpp-httplib reads it
// (the pre-routing handler sees only the headers), released when the reply is made.
thread_local MemoryBudget::Reservation body_reservation;
}  // namespace

BridgeServer::BridgeServer(BridgeApi& api, const OriginPolicy& origins, MemoryBudget& budget, const ServeLimits& limits)
    : api_(api), origins_(origins), budget_(budget), limits_(limits), server_(std::make_unique<httplib::Server>()) {}

BridgeServer::~BridgeServer() { stop(); }

void BridgeServer::add_routes() {
  auto& s = *server_;
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    const std::string origin = req.get_header_value("Origin");
    const bool host_ok = !check_host_ || OriginPolicy::is_loopback_host(req.get_header_value("Host"));
    if (origins_.allows(origin, req.get_header_value("Host")) && host_ok) {
      if (!origin.empty()) {
        res.set_header("Access-Control-Allow-Origin", origin);
        res.set_header("Vary", "Origin");
      }
      // Beyond loopback: the token, or only the login form (docs/console.md, "Security").
      if (!origins_.token_ok(OriginPolicy::from_this_machine(req.remote_addr, req.get_header_value("Host")),
                             req.get_header_value("Cookie"), req.get_header_value("Authorization")) &&
          !(console_ && ConsoleRoutes::is_login(req))) {  // the login form's post checks the token itself
        if (console_ && console_->answer_without_token(req, res)) return httplib::Server::HandlerResponse::Handled;
        ++refused_;
        res.status = 401;
        res.set_content(bridge_reply("refused", "", wstring("value", "the access token is needed"), "Failure").dump(),
                        "application/json");
        return httplib::Server::HandlerResponse::Handled;
      }
      // Only an upload's body may be larger than a Bridge body (the server's limit is the
      // larger): the PUT/POST routes read theirs with their own bound (bounded_body.hpp) and
      // answer 413; a large body anywhere else is refused unread (no client sends one).
      const bool upload = console_ && req.path == kUploadPath;
      const bool bounded_route = (req.method == "PUT" || req.method == "POST") && ConsoleRoutes::reads_bounded_body(req.path);
      const bool chunked = req.get_header_value_count("Transfer-Encoding") > 0;
      if (!upload && (chunked || (!bounded_route && req.get_header_value<std::uint64_t>("Content-Length") > limits_.max_body_bytes))) {
        res.status = chunked ? 411 : 413;
        res.set_header("Connection", "close");
        return httplib::Server::HandlerResponse::Handled;
      }
      // An upload goes to a file as it arrives: what it holds in memory is a read buffer.
      if (upload && req.get_header_value<std::uint64_t>("Content-Length") > max_upload_bytes_) {
        res.status = 413;
        res.set_content(nlohmann::json{{"error", fmt::format("larger than the upload limit of {} MiB", max_upload_bytes_ >> 20)}}.dump(),
                        "application/json");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (upload) return httplib::Server::HandlerResponse::Unhandled;
      // The body as read, parsed to JSON and copied once more: three times its length. One
      // over the body limit is cpp-httplib's 413, not ours.
      const std::size_t length = std::min(req.get_header_value<std::uint64_t>("Content-Length"), std::uint64_t(limits_.max_body_bytes));
      body_reservation.release();  // a request that never reached post-routing (a 413, say)
      body_reservation = budget_.try_reserve(3 * length);
      if (length == 0 || body_reservation) return httplib::Server::HandlerResponse::Unhandled;
      res.status = 503;
      res.set_header("Retry-After", "1");
      res.set_content(bridge_reply("busy", "", wstring("value", "busy: the service's memory budget is in use; try again"),
                                   "Failure").dump(),
                      "application/json");
      return httplib::Server::HandlerResponse::Handled;
    }
    ++refused_;
    spdlog::warn("bridge: refused {} {} ({})", req.method, req.path.substr(0, 64),
                 host_ok ? "origin " + origin.substr(0, 200) : "host " + req.get_header_value("Host").substr(0, 200));
    res.status = 403;
    res.set_content(bridge_reply("refused", "", wstring("value", "origin not allowed"), "Failure").dump(),
                    "application/json");
    return httplib::Server::HandlerResponse::Handled;
  });
  s.set_post_routing_handler([](const httplib::Request&, httplib::Response&) { body_reservation.release(); });
  if (console_) console_->add_routes(s);  // its GET / answers scripts as the one below
  s.Get("/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(R"({"service":"lfd serve"})", "application/json");
  });
  s.Options(R"(/.*)", [](const httplib::Request&, httplib::Response& res) {
    res.set_header("Access-Control-Allow-Methods", "PUT, POST, GET, OPTIONS");
    res.set_header("Access-Control-Allow-Headers", "Content-Type");
    res.set_header("Access-Control-Allow-Private-Network", "true");
    res.status = 204;
  });
  // bridge.js and the vendor's ComfyUI node send PUT, other scripts POST: the same call either way.
  const auto call = [this](const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& read) {
    const auto body = read_bounded_body(read, limits_.max_body_bytes);
    if (!body) {
      res.status = 413;
      return;
    }
    const BridgeResponse reply = api_.handle(req.matches[1].str(), *body);
    res.status = reply.http_status;
    if (reply.http_status == 503) res.set_header("Retry-After", "1");  // busy: the budget is in use
    res.set_content(reply.body, "application/json");
  };
  s.Put(R"(/([A-Za-z_]{1,64}))", call);
  s.Post(R"(/([A-Za-z_]{1,64}))", call);
}

void BridgeServer::start(const ListenAddress& address) {
  check_host_ = address.is_loopback();
  auto& s = *server_;
  s.new_task_queue = [this] { return new BoundedTaskQueue(limits_.worker_threads * 4, limits_.max_connections); };
  s.set_payload_max_length(std::max(limits_.max_body_bytes, max_upload_bytes_));
  s.set_read_timeout(limits_.io_timeout_s, 0);
  s.set_write_timeout(limits_.io_timeout_s, 0);
  s.set_keep_alive_timeout(2);
  s.set_keep_alive_max_count(100);
  add_routes();
  if (!s.bind_to_port(address.host, address.bridge_port))
    throw std::runtime_error(fmt::format("http://{}:{}: cannot listen (in use?)", address.url_host(), address.bridge_port));
  thread_ = std::thread([this] { server_->listen_after_bind(); });
}

void BridgeServer::stop() {
  if (!thread_.joinable()) return;
  server_->stop();
  thread_.join();
}

}  // namespace lfd::serve
