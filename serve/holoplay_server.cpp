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

// One REP context: receives a request, has it answered (now or by a lane), sends the reply,
// and receives again, until the socket closes.
struct HoloPlayServer::Context {
  HoloPlayServer* server = nullptr;
  nng_ctx ctx = NNG_CTX_INITIALIZER;
  nng_aio* aio = nullptr;
  bool sending = false;
};

void HoloPlayServer::start(const ListenAddress& address) {
  check(nng_rep0_open(&socket_), "holoplay: REP socket");
  open_ = true;
  stopping_ = false;
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
  // Each lane holds at most one job per context, so its queue never makes a context wait.
  small_lane_ = std::make_unique<BoundedTaskQueue>(2, limits_.max_connections);
  content_lane_ = std::make_unique<BoundedTaskQueue>(limits_.worker_threads, limits_.max_connections);
  for (int i = 0; i < limits_.max_connections; ++i) {
    auto c = std::make_unique<Context>();
    c->server = this;
    check(nng_ctx_open(&c->ctx, socket_), "holoplay: REP context");
    check(nng_aio_alloc(&c->aio, &HoloPlayServer::on_context_event, c.get()), "holoplay: REP context");
    contexts_.push_back(std::move(c));
  }
  check(nng_listener_start(listener, 0), url);
  for (auto& c : contexts_) nng_ctx_recv(c->ctx, c->aio);
}

void HoloPlayServer::on_context_event(void* arg) {
  Context& c = *static_cast<Context*>(arg);
  HoloPlayServer& self = *c.server;
  const int result = nng_aio_result(c.aio);
  if (c.sending) {
    c.sending = false;
    if (result != 0) nng_msg_free(nng_aio_get_msg(c.aio));  // the reply was not taken
    else ++self.answered_;
  } else if (result == 0) {
    self.received(c);
    return;
  }
  if (result == NNG_ECLOSED || result == NNG_ECANCELED || self.stopping_) return;
  nng_ctx_recv(c.ctx, c.aio);
}

// On NNG's thread: decides at once, never decodes here.
void HoloPlayServer::received(Context& c) {
  nng_msg* request = nng_aio_get_msg(c.aio);
  const std::size_t bytes = nng_msg_len(request);
  const std::span<const std::uint8_t> payload(static_cast<const std::uint8_t*>(nng_msg_body(request)), bytes);
  if (!protocol_.carries_content(payload, kSmallRequestBytes)) {
    small_lane_->enqueue([this, &c, request] { handle_in_lane(c, request, {}, false); });
    return;
  }
  // Content: a free content worker and the budget for the message's copies now, or busy now.
  MemoryBudget::Reservation held;
  if (++content_in_flight_ <= limits_.worker_threads) held = protocol_.admit(bytes);
  if (!held) {
    --content_in_flight_;
    answer(c, request, protocol_.busy_reply("busy: the service is handling as much content as it holds; try again"));
    return;
  }
  // std::function copies its target: the reservation travels in a shared holder.
  auto admitted = std::make_shared<MemoryBudget::Reservation>(std::move(held));
  content_lane_->enqueue([this, &c, request, admitted] { handle_in_lane(c, request, std::move(*admitted), true); });
}

void HoloPlayServer::handle_in_lane(Context& c, nng_msg* request, MemoryBudget::Reservation held, bool content) {
  std::vector<std::uint8_t> reply;
  if (stopping_) {
    reply = protocol_.busy_reply("busy: the service is stopping");
  } else {
    const std::span<const std::uint8_t> payload(static_cast<const std::uint8_t*>(nng_msg_body(request)),
                                                nng_msg_len(request));
    reply = protocol_.handle(payload, std::move(held));
  }
  if (content) --content_in_flight_;
  answer(c, request, std::move(reply));
}

// Frees the request before the reply goes out: a quilt's bytes are not held while it is sent.
void HoloPlayServer::answer(Context& c, nng_msg* request, std::vector<std::uint8_t> reply) {
  nng_msg* out = nullptr;
  if (nng_msg_alloc(&out, 0) != 0 || nng_msg_append(out, reply.data(), reply.size()) != 0 ||
      nng_msg_header_append(out, nng_msg_header(request), nng_msg_header_len(request)) != 0) {
    if (out) nng_msg_free(out);
    nng_msg_free(request);
    if (!stopping_) nng_ctx_recv(c.ctx, c.aio);  // this request goes unanswered; the next is taken
    return;
  }
  nng_msg_free(request);
  c.sending = true;
  nng_aio_set_msg(c.aio, out);
  nng_ctx_send(c.ctx, c.aio);
}

void HoloPlayServer::stop() {
  if (!open_) return;
  open_ = false;
  stopping_ = true;
  nng_close(socket_);  // every context's receive or send ends with NNG_ECLOSED
  small_lane_->shutdown();
  content_lane_->shutdown();
  for (auto& c : contexts_) {
    nng_aio_stop(c->aio);
    nng_aio_free(c->aio);
  }
  contexts_.clear();
}

}  // namespace lfd::serve
