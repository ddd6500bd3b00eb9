// The Origin allow-list (docs/serve.md, "Security model").
#include "serve/origin_policy.hpp"

#include <algorithm>
#include <cctype>

namespace lfd::serve {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// "localhost", "127.0.0.1", "[::1]", each with an optional ":port" of digits.
bool is_loopback_authority(std::string_view authority) {
  for (std::string_view host : {"localhost", "127.0.0.1", "[::1]"}) {
    if (authority.substr(0, host.size()) != host) continue;
    std::string_view rest = authority.substr(host.size());
    if (rest.empty()) return true;
    if (rest[0] != ':' || rest.size() < 2 || rest.size() > 6) continue;
    if (std::all_of(rest.begin() + 1, rest.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return true;
  }
  return false;
}

}  // namespace

OriginPolicy::OriginPolicy(std::vector<std::string> extra_origins) : extra_(std::move(extra_origins)) {
  for (auto& o : extra_) {
    o = lower(o);
    while (!o.empty() && o.back() == '/') o.pop_back();
  }
}

bool OriginPolicy::allows(std::string_view origin_header) const {
  if (origin_header.empty()) return true;  // not a browser
  const std::string origin = lower(origin_header);
  if (std::find(extra_.begin(), extra_.end(), origin) != extra_.end()) return true;
  if (origin.rfind("file://", 0) == 0) return true;
  for (std::string_view scheme : {"http://", "https://"})
    if (origin.rfind(scheme, 0) == 0) return is_loopback_authority(std::string_view(origin).substr(scheme.size()));
  return false;
}

bool OriginPolicy::allows(std::string_view origin_header, std::string_view host_header) const {
  if (allows(origin_header)) return true;
  if (console_port_ <= 0 || host_header.empty() || host_header.size() > 300) return false;
  // The host part of Host ("name:port", "[v6]:port", "name"), then the console's port.
  std::string host = lower(host_header);
  const std::size_t bracket = host.rfind(']');
  const std::size_t colon = host.rfind(':');
  if (colon != std::string::npos && (bracket == std::string::npos || colon > bracket)) host.resize(colon);
  return lower(origin_header) == "http://" + host + ":" + std::to_string(console_port_);
}

bool OriginPolicy::from_this_machine(std::string_view peer, std::string_view host_header) {
  const bool loopback_peer = peer.rfind("127.", 0) == 0 || peer == "::1" || peer.rfind("::ffff:127.", 0) == 0;
  return loopback_peer && is_loopback_host(host_header);
}

bool OriginPolicy::is_loopback_host(std::string_view host_header) {
  return is_loopback_authority(lower(host_header));
}

}  // namespace lfd::serve
