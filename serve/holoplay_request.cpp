// Parsing HoloPlay Service requests (docs/serve.md).
#include "serve/holoplay_request.hpp"

#include <cmath>

#include "util/error.hpp"

namespace lfd::serve {

HoloPlayRequest parse_holoplay_request(std::span<const std::uint8_t> payload, const CborLimits& limits) {
  const nlohmann::json root = decode_cbor(payload, limits);
  if (!root.is_object()) throw_input_error("request: not a CBOR map");
  const auto cmd = root.find("cmd");
  if (cmd == root.end() || !cmd->is_object() || cmd->size() != 1)
    throw_input_error("request: cmd: not a map with one command");
  HoloPlayRequest request;
  request.command = cmd->begin().key();
  const nlohmann::json& args = cmd->begin().value();
  if (args.is_object()) request.args = args;
  else if (args.is_null()) request.args = nlohmann::json::object();
  else throw_input_error("request: cmd.{}: not a map", request.command.substr(0, 64));
  const auto bin = root.find("bin");
  if (bin != root.end()) {
    if (bin->is_binary()) request.bin = bin->get_binary();
    else if (!bin->is_null() && !(bin->is_string() && bin->get_ref<const std::string&>().empty()))
      throw_input_error("request: bin: not a byte string");
  }
  return request;
}

namespace {

int tile_count(const nlohmann::json& s, const char* key) {
  const auto it = s.find(key);
  if (it == s.end() || !it->is_number()) throw_input_error("quilt settings: {}: missing or not a number", key);
  const double v = it->get<double>();
  if (!std::isfinite(v) || v != std::floor(v) || v < 1 || v > 100)
    throw_input_error("quilt settings: {}: {} is not a whole number in 1..100", key, v);
  return static_cast<int>(v);
}

}  // namespace

QuiltSettings holoplay_quilt_settings(const nlohmann::json& s) {
  if (!s.is_object()) throw_input_error("quilt settings: not a map");
  QuiltSettings q;
  q.cols = tile_count(s, "vx");
  q.rows = tile_count(s, "vy");
  q.views = q.cols * q.rows;
  if (const auto t = s.find("vtotal"); t != s.end() && !t->is_null()) {
    if (!t->is_number()) throw_input_error("quilt settings: vtotal: not a number");
    const double v = t->get<double>();
    if (!std::isfinite(v) || v != std::floor(v) || v < 1 || v > q.views)
      throw_input_error("quilt settings: vtotal: {} is not in 1..vx*vy", v);
    q.views = static_cast<int>(v);
  }
  const auto a = s.find("aspect");
  if (a == s.end() || !a->is_number()) throw_input_error("quilt settings: aspect: missing or not a number");
  q.aspect = a->get<double>();
  if (!std::isfinite(q.aspect) || q.aspect <= 0 || q.aspect > 100)
    throw_input_error("quilt settings: aspect: {} is not in (0, 100]", q.aspect);
  return q;
}

}  // namespace lfd::serve
