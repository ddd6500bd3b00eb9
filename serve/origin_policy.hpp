#pragma once
// Which web pages may drive the display (docs/serve.md, "Security model"). Browsers send an
// Origin header with every WebSocket handshake and every cross-origin PUT; a page on another
// site is refused (403 / the WebSocket closed before any message) and changes nothing.
// Programs that are not browsers (node, Blender, curl) send none and are let in: they run as
// the user already. Loopback pages (http(s)://localhost, 127.0.0.1, [::1], any port) and
// file:// pages are allowed by default; `--allow-origin URL` adds exact origins ("null" lets
// in Chromium's file:// pages, and also sandboxed frames of any site: say so before adding it).
#include <string>
#include <string_view>
#include <vector>

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

 private:
  std::vector<std::string> extra_;
};

}  // namespace lfd::serve
