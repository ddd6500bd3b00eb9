// libFuzzer target: a HoloPlay Service request as the endpoint reads it off a connection: its SP
// header (serve/sp_header.hpp), then its CBOR payload (serve::parse_holoplay_request, libcbor
// behind a streaming pre-check of sizes and depth; docs/serve.md); the payload alone too. Any input must parse
// or throw lfd::InputError; what parses must encode back to CBOR and decode to the same JSON.
// Anything else (a crash, a sanitizer report, another exception, an allocation beyond
// -rss_limit_mb from a lying length) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "serve/cbor_json.hpp"
#include "serve/holoplay_request.hpp"
#include "serve/sp_header.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const lfd::serve::CborLimits limits{16, 1u << 20};
  const std::span<const std::uint8_t> message(data, size);
  if (const auto header = lfd::serve::sp_header_length(message)) {
    if (*header > size || *header % 4 != 0 || !(data[*header - 4] & 0x80)) std::abort();
    try {
      lfd::serve::parse_holoplay_request(message.subspan(*header), limits);
    } catch (const lfd::InputError&) {
    }
  }
  const std::span<const std::uint8_t> bytes = message;
  try {
    const lfd::serve::HoloPlayRequest request = lfd::serve::parse_holoplay_request(bytes, limits);
    if (request.command.empty() && !request.args.is_object()) std::abort();
    if (request.args.contains("settings")) {
      try {
        lfd::serve::holoplay_quilt_settings(request.args["settings"]);
      } catch (const lfd::InputError&) {
      }
    }
  } catch (const lfd::InputError&) {
  }
  try {
    const nlohmann::json value = lfd::serve::decode_cbor(bytes, limits);
    const auto again = lfd::serve::decode_cbor(lfd::serve::encode_cbor(value), limits);
    // NaN is not equal to itself: compare the text forms.
    if (again.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) !=
        value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace))
      std::abort();
  } catch (const lfd::InputError&) {
  }
  return 0;
}
