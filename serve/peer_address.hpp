#pragma once
// A WebSocket peer's address as text for OriginPolicy::from_this_machine (docs/console.md,
// "Security"): "127.0.0.1", "::1", "::ffff:127.0.0.1" or another address; "" when unknown.
#include <arpa/inet.h>

#include <cstring>
#include <string>

#include <nng/nng.h>

namespace lfd::serve {

inline std::string peer_address_text(const nng_sockaddr& address) {
  char text[INET6_ADDRSTRLEN] = {};
  if (address.s_family == NNG_AF_INET) {
    in_addr a{};
    a.s_addr = address.s_in.sa_addr;  // network byte order, as NNG keeps it
    return inet_ntop(AF_INET, &a, text, sizeof text) ? text : "";
  }
  if (address.s_family == NNG_AF_INET6) {
    in6_addr a{};
    std::memcpy(&a, address.s_in6.sa_addr, sizeof a);
    return inet_ntop(AF_INET6, &a, text, sizeof text) ? text : "";
  }
  return "";
}

}  // namespace lfd::serve
