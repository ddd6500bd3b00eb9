#pragma once
// CBOR (RFC 8949) to and from nlohmann::json through libcbor, for the HoloPlay Service protocol
// (docs/serve.md). Byte strings become json binary values. Decoding first walks the message
// with libcbor's streaming decoder and refuses, before anything is allocated, nesting deeper
// than the limit, more items than the limit, and containers that claim more items than bytes
// remain (a few bytes must not make libcbor allocate gigabytes).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

namespace lfd::serve {

struct CborLimits {
  int max_depth = 16;
  std::size_t max_items = 1u << 20;
};

// One CBOR data item filling all of `bytes`; map keys must be text. Throws InputError.
nlohmann::json decode_cbor(std::span<const std::uint8_t> bytes, const CborLimits& limits);

std::vector<std::uint8_t> encode_cbor(const nlohmann::json& value);

}  // namespace lfd::serve
