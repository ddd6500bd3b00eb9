#pragma once
// Where the service listens (docs/serve.md, "Security model"): loopback by default; `--listen`
// names another address, and the service says so at start.
#include <string>
#include <vector>

namespace lfd::serve {

struct ListenAddress {
  std::string host = "127.0.0.1";
  int holoplay_port = 11222;  // ws://host:11222/driver
  int bridge_port = 33334;    // http://host:33334/<endpoint>
  int events_port = 9724;     // ws://host:9724/event_source

  bool is_loopback() const { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }
  // The URL host NNG's WebSocket listeners bind: NNG's HTTP server answers 404 unless a
  // request's Host header names the URL's host, and the clients dial "localhost"
  // (holoplay-core, bridge.js, AliceLG), so the loopback address is listened on by that name.
  std::string ws_host() const { return is_loopback() && host != "::1" ? "localhost" : url_host(); }
  // NNG wants "[::1]" for IPv6 in a URL.
  std::string url_host() const { return host.find(':') != std::string::npos ? "[" + host + "]" : host; }
};

}  // namespace lfd::serve
