#pragma once
// The nanomsg SP header a REQ peer puts before each request over WebSocket (docs/serve.md,
// "HoloPlay Service protocol"): echoed before the reply so the client matches it to its request.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace lfd::serve {

// The length of a request's SP header: 4-byte words up to and including the one with its high
// bit set (the request id; those before it are hops of a device, at most 8 as in NNG), or none
// when the message has no such word.
inline std::optional<std::size_t> sp_header_length(std::span<const std::uint8_t> message) {
  constexpr std::size_t kMaxWords = 8;
  for (std::size_t word = 0; word < kMaxWords && 4 * word + 4 <= message.size(); ++word)
    if (message[4 * word] & 0x80) return 4 * word + 4;
  return std::nullopt;
}

}  // namespace lfd::serve
