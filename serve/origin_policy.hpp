#pragma once
// Which web pages may drive the display (docs/serve.md, "Security model"). Browsers send an
// Origin header with every WebSocket handshake and every cross-origin PUT; a page on another
// site is refused (403 / the WebSocket closed before any message) and changes nothing.
// Programs that are not browsers (node, Blender, curl) send none and are let in: they run as
// the user already. Loopback pages (http(s)://localhost, 127.0.0.1, [::1], any port) and
// file:// pages are allowed by default; `--allow-origin URL` adds exact origins ("null" lets
// in Chromium's file:// pages, and also sandboxed frames of any site: say so before adding it).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "serve/access_token.hpp"

namespace lfd::serve {

class OriginPolicy {
 public:
  explicit OriginPolicy(std::vector<std::string> extra_origins = {});
  // `origin` is the header's value; absent header: empty.
  bool allows(std::string_view origin) const;
  // The Host header of an HTTP request to a loopback listener must name a loopback host
  // (against DNS rebinding: a foreign name resolved to 127.0.0.1).
  static bool is_loopback_host(std::string_view host_header);
  const std::vector<std::string>& extra_origins() const { return extra_; }

  // The console page's own origin (docs/console.md): http://<the host the request was sent
  // to>:<console_port>, whatever address the service listens on; allowed besides the above.
  void set_console_port(int port) { console_port_ = port; }
  bool allows(std::string_view origin, std::string_view host_header) const;
  // Beyond loopback (--listen) every request carries the access token; none set: not needed.
  void require_token(AccessToken token) { token_ = std::move(token); }
  bool token_required() const { return token_.has_value(); }
  // A request from this machine (a loopback peer that named a loopback Host: no DNS rebinding)
  // needs no token: only those from off the machine do.
  bool token_ok(bool from_this_machine, std::string_view cookie_header, std::string_view authorization_header) const {
    return !token_ || from_this_machine || token_->carried_by(cookie_header, authorization_header);
  }
  // The peer's address as text ("127.0.0.1", "::1", "::ffff:127.0.0.1") and the Host header.
  static bool from_this_machine(std::string_view peer_address, std::string_view host_header);
  const std::optional<AccessToken>& token() const { return token_; }

 private:
  std::vector<std::string> extra_;
  int console_port_ = 0;
  std::optional<AccessToken> token_;
};

}  // namespace lfd::serve
