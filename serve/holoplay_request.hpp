#pragma once
// A HoloPlay Service request (holoplay-core's protocol, docs/serve.md "Sources"): the CBOR map
// `{cmd: {<command>: {...}}, bin: <bytes>}` that holoplay-core sends after NNG's 4-byte request
// id (which NNG's REP socket strips). The parser the fuzz target `fuzz_holoplay_request` drives.
#include <cstdint>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "serve/cbor_json.hpp"
#include "serve/display_service.hpp"

namespace lfd::serve {

struct HoloPlayRequest {
  std::string command;               // "init", "info", "show", ...
  nlohmann::json args;               // the command's map (an empty object when absent)
  nlohmann::json::binary_t bin;      // the image of show/cache; empty when none
};

// Throws InputError naming the field.
HoloPlayRequest parse_holoplay_request(std::span<const std::uint8_t> payload, const CborLimits& limits);

// holoplay-core's quilt settings `{vx, vy, vtotal?, aspect}` checked (1..100 tiles a side,
// 1 <= vtotal <= vx * vy, 0 < aspect <= 100). Throws InputError naming the field.
QuiltSettings holoplay_quilt_settings(const nlohmann::json& settings);

}  // namespace lfd::serve
