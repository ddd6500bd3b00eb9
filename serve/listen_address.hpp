#pragma once
// Where the service listens (docs/serve.md, "Security model"): loopback by default; `--listen`
// names another address, and the service says so at start.
#include <string>

namespace lfd::serve {

struct ListenAddress {
  std::string host = "127.0.0.1";
  int holoplay_port = 11222;  // ws://host:11222/driver
  int bridge_port = 33334;    // http://host:33334/<endpoint>
  int events_port = 9724;     // ws://host:9724/event_source

  bool is_loopback() const { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }
  // NNG wants "[::1]" for IPv6 in a URL.
  std::string url_host() const { return host.find(':') != std::string::npos ? "[" + host + "]" : host; }
};

}  // namespace lfd::serve
