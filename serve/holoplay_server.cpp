// The HoloPlay Service endpoint on NNG (docs/serve.md, "HoloPlay Service protocol").
#include "serve/holoplay_server.hpp"

#include "serve/peer_address.hpp"

#include <nng/protocol/reqrep0/rep.h>
#include <nng/supplemental/util/platform.h>

#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace lfd::serve {

namespace {

std::string pipe_header(nng_pipe pipe, const char* header) {
  char* value = nullptr;
  const std::string option = std::string(NNG_OPT_WS_REQUEST_HEADER) + header;
  if (nng_pipe_get_string(pipe, option.c_str(), &value) != 0 || !value) return {};
  std::string out(value);
  nng_strfree(value);
  return out;
}

bool from_this_machine(nng_pipe pipe) {
  nng_sockaddr peer{};
  if (nng_pipe_get_addr(pipe, NNG_OPT_REMADDR, &peer) != 0) return false;
  return OriginPolicy::from_this_machine(peer_address_text(peer), pipe_header(pipe, "Host"));
}

void check(int rv, const std::string& what) {
  if (rv != 0) throw std::runtime_error(fmt::format("{}: {}", what, nng_strerror(rv)));
}

}  // namespace

HoloPlayServer::HoloPlayServer(HoloPlayProtocol& protocol, const OriginPolicy& origins, const ServeLimits& limits)
    : protocol_(protocol), origins_(origins), limits_(limits) {}

HoloPlayServer::~HoloPlayServer() { stop(); }

void HoloPlayServer::on_pipe(nng_pipe pipe, nng_pipe_ev event, void* arg) {
  auto* self = static_cast<HoloPlayServer*>(arg);
  if (event == NNG_PIPE_EV_REM_POST) {
    --self->connections_;
    return;
  }
  if (event != NNG_PIPE_EV_ADD_PRE) return;
  const std::string origin = pipe_header(pipe, "Origin");
  if (!self->origins_.allows(origin) ||
      !self->origins_.token_ok(from_this_machine(pipe), pipe_header(pipe, "Cookie"), pipe_header(pipe, "Authorization"))) {
    ++self->refused_;
    spdlog::warn("holoplay: refused a connection from origin {}", origin.substr(0, 200));
    nng_pipe_close(pipe);
    return;
  }
  if (++self->connections_ > self->limits_.max_connections) {
    ++self->refused_;
    spdlog::warn("holoplay: refused a connection over the limit of {}", self->limits_.max_connections);
    nng_pipe_close(pipe);  // REM_POST follows and gives the count back
  }
}

void HoloPlayServer::start(const ListenAddress& address) {
  check(nng_rep0_open(&socket_), "holoplay: REP socket");
  open_ = true;
  check(nng_socket_set_size(socket_, NNG_OPT_RECVMAXSZ, limits_.max_message_bytes), "holoplay: REP socket");
  check(nng_socket_set_ms(socket_, NNG_OPT_SENDTIMEO, limits_.io_timeout_s * 1000), "holoplay: REP socket");
  nng_pipe_notify(socket_, NNG_PIPE_EV_ADD_PRE, &HoloPlayServer::on_pipe, this);
  nng_pipe_notify(socket_, NNG_PIPE_EV_REM_POST, &HoloPlayServer::on_pipe, this);
  const std::string url = fmt::format("ws://{}:{}/driver", address.ws_host(), address.holoplay_port);
  nng_listener listener;
  check(nng_listener_create(&listener, socket_, url.c_str()), url);
  check(nng_listener_set_size(listener, NNG_OPT_RECVMAXSZ, limits_.max_message_bytes), url);
  // Browsers and `ws` send a message as one frame: NNG's 1 MiB frame default would drop quilts.
  check(nng_listener_set_size(listener, NNG_OPT_WS_RECVMAXFRAME, limits_.max_message_bytes), url);
  check(nng_listener_start(listener, 0), url);
  for (int i = 0; i < limits_.worker_threads; ++i) workers_.emplace_back([this] { work(); });
}

// One REP context per worker: receive, answer, repeat until the socket closes.
void HoloPlayServer::work() {
  nng_ctx ctx;
  if (nng_ctx_open(&ctx, socket_) != 0) return;
  nng_aio* aio = nullptr;
  if (nng_aio_alloc(&aio, nullptr, nullptr) != 0) return;
  for (;;) {
    nng_ctx_recv(ctx, aio);
    nng_aio_wait(aio);
    if (nng_aio_result(aio) == NNG_ECLOSED) break;
    if (nng_aio_result(aio) != 0) continue;
    nng_msg* request = nng_aio_get_msg(aio);
    const std::span<const std::uint8_t> payload(static_cast<const std::uint8_t*>(nng_msg_body(request)),
                                                nng_msg_len(request));
    const std::vector<std::uint8_t> reply = protocol_.handle(payload);
    nng_msg_clear(request);
    if (nng_msg_append(request, reply.data(), reply.size()) != 0) {
      nng_msg_free(request);
      continue;
    }
    nng_aio_set_msg(aio, request);
    nng_ctx_send(ctx, aio);
    nng_aio_wait(aio);
    if (nng_aio_result(aio) != 0) nng_msg_free(nng_aio_get_msg(aio));
    else ++answered_;
    if (nng_aio_result(aio) == NNG_ECLOSED) break;
  }
  nng_aio_free(aio);
  nng_ctx_close(ctx);
}

void HoloPlayServer::stop() {
  if (!open_) return;
  open_ = false;
  nng_close(socket_);
  for (auto& t : workers_) t.join();
  workers_.clear();
}

}  // namespace lfd::serve
