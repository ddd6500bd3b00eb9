#pragma once
// A Bridge HTTP API request body (docs/serve.md "Bridge HTTP API"): a JSON object, parsed
// under the body limit and a nesting limit (nlohmann's parser recurses), and its fields read
// with their types and ranges checked. The parser the fuzz target `fuzz_bridge_request` drives.
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace lfd::serve {

inline constexpr int kMaxJsonDepth = 32;

// An empty body is an empty object. Throws InputError.
nlohmann::json parse_bridge_request(std::string_view body, std::size_t max_bytes);
// Any JSON document under the size and nesting limits (a file a request names, such as a Studio
// playlist); InputError "<what>: ...".
nlohmann::json parse_bounded_json(std::string_view text, std::size_t max_bytes, const std::string& what);

// Field readers; a missing field gives `fallback`, a wrong one throws InputError naming it.
// Numbers may come as JSON numbers or as numeric text (bridge.js sends update_current_entry's
// values as `${value}`).
double field_number(const nlohmann::json& request, const char* key, double min, double max, double fallback);
int field_int(const nlohmann::json& request, const char* key, int min, int max, int fallback);
bool field_bool(const nlohmann::json& request, const char* key, bool fallback);
std::string field_text(const nlohmann::json& request, const char* key, std::size_t max_chars,
                       const std::string& fallback);

}  // namespace lfd::serve
