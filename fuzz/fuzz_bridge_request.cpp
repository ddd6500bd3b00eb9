// libFuzzer target: a Bridge HTTP API request body (serve::parse_bridge_request and the field
// readers the endpoints use; docs/serve.md). Any input must parse or throw lfd::InputError,
// nesting never reaches nlohmann's recursion, and a field read either returns a value in its
// range or throws lfd::InputError.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "serve/bridge_request.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view body(reinterpret_cast<const char*>(data), size);
  nlohmann::json request;
  try {
    request = lfd::serve::parse_bridge_request(body, 1u << 20);
  } catch (const lfd::InputError&) {
    return 0;
  }
  if (!request.is_object()) std::abort();
  for (const char* key : {"orchestration", "name", "uri", "rows", "cols", "aspect", "focus", "index", "loop"}) {
    try {
      const double x = lfd::serve::field_number(request, key, -10, 10, 0);
      if (!std::isfinite(x) || x < -10 || x > 10) std::abort();
    } catch (const lfd::InputError&) {
    }
    try {
      const int n = lfd::serve::field_int(request, key, 1, 100, 1);
      if (n < 1 || n > 100) std::abort();
    } catch (const lfd::InputError&) {
    }
    try {
      if (lfd::serve::field_text(request, key, 256, "").size() > 256) std::abort();
    } catch (const lfd::InputError&) {
    }
    try {
      lfd::serve::field_bool(request, key, false);
    } catch (const lfd::InputError&) {
    }
  }
  return 0;
}
