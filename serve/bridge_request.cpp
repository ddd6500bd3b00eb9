// Parsing Bridge request bodies (docs/serve.md, "Bridge HTTP API").
#include "serve/bridge_request.hpp"

#include <charconv>
#include <cmath>

#include "util/error.hpp"

namespace lfd::serve {

namespace {

// The deepest nesting of arrays and objects outside strings.
int nesting_depth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

const nlohmann::json* find(const nlohmann::json& r, const char* key) {
  const auto it = r.find(key);
  return it == r.end() || it->is_null() ? nullptr : &*it;
}

double number_of(const nlohmann::json& v, const char* key) {
  if (v.is_number()) return v.get<double>();
  if (v.is_boolean()) return v.get<bool>() ? 1 : 0;
  if (v.is_string()) {
    const auto& s = v.get_ref<const std::string&>();
    double out = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ec == std::errc() && end == s.data() + s.size()) return out;
  }
  throw_input_error("{}: not a number", key);
}

}  // namespace

nlohmann::json parse_bounded_json(std::string_view text, std::size_t max_bytes, const std::string& what) {
  if (text.size() > max_bytes) throw_input_error("{}: larger than {} bytes", what, max_bytes);
  if (nesting_depth(text) > kMaxJsonDepth) throw_input_error("{}: nested deeper than {}", what, kMaxJsonDepth);
  nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  if (document.is_discarded()) throw_input_error("{}: not JSON", what);
  return document;
}

nlohmann::json parse_bridge_request(std::string_view body, std::size_t max_bytes) {
  if (body.size() <= max_bytes && body.find_first_not_of(" \t\r\n") == std::string_view::npos)
    return nlohmann::json::object();
  nlohmann::json request = parse_bounded_json(body, max_bytes, "body");
  if (!request.is_object()) throw_input_error("body: not a JSON object");
  return request;
}

double field_number(const nlohmann::json& r, const char* key, double min, double max, double fallback) {
  const nlohmann::json* v = find(r, key);
  if (!v) return fallback;
  const double x = number_of(*v, key);
  if (!std::isfinite(x) || x < min || x > max) throw_input_error("{}: {} is not in [{}, {}]", key, x, min, max);
  return x;
}

int field_int(const nlohmann::json& r, const char* key, int min, int max, int fallback) {
  const double x = field_number(r, key, min, max, fallback);
  if (x != std::floor(x)) throw_input_error("{}: {} is not a whole number", key, x);
  return static_cast<int>(x);
}

bool field_bool(const nlohmann::json& r, const char* key, bool fallback) {
  const nlohmann::json* v = find(r, key);
  if (!v) return fallback;
  if (v->is_string()) {
    const auto& s = v->get_ref<const std::string&>();
    if (s == "true") return true;
    if (s == "false") return false;
  }
  const double x = number_of(*v, key);
  if (x != 0 && x != 1) throw_input_error("{}: not a boolean", key);
  return x == 1;
}

std::string field_text(const nlohmann::json& r, const char* key, std::size_t max_chars, const std::string& fallback) {
  const nlohmann::json* v = find(r, key);
  if (!v) return fallback;
  if (!v->is_string()) throw_input_error("{}: not text", key);
  const auto& s = v->get_ref<const std::string&>();
  if (s.size() > max_chars) throw_input_error("{}: longer than {} characters", key, max_chars);
  return s;
}

}  // namespace lfd::serve
