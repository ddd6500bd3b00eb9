#include "bridge_inproc/bridge_settings.hpp"

#include <cstdlib>

#include <nlohmann/json.hpp>

#include "display/visual_json.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::bridge {

std::filesystem::path lfd_settings_path() {
  if (const char* p = std::getenv("LFD_BRIDGE_CONFIG"); p && *p) return p;
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home ? home : ".") / ".config" / "lfd" / "bridge.json";
}

LfdBridgeSettings parse_lfd_settings(const std::string& text, const std::string& name) {
  const nlohmann::ordered_json root = display::parse_json_object(text, name);
  LfdBridgeSettings s;
  const auto string_field = [&](const char* key, std::string& out) {
    if (!root.contains(key)) return;
    if (!root[key].is_string()) throw_input_error("{}: {}: not a string", name, key);
    out = root[key].get<std::string>();
  };
  string_field("device", s.device);
  string_field("monitor", s.monitor);
  string_field("gl", s.gl);
  gpu::parse_gl_request(s.gl, name + ": gl");  // refused here, not at the first window
  if (root.contains("calibrations")) {
    const auto& list = root["calibrations"];
    if (!list.is_array()) throw_input_error("{}: calibrations: not an array", name);
    for (const auto& item : list) {
      if (!item.is_string()) throw_input_error("{}: calibrations: an entry is not a string", name);
      s.calibrations.push_back(item.get<std::string>());
    }
  }
  return s;
}

LfdBridgeSettings read_lfd_settings(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) return {};
  return parse_lfd_settings(read_text_file(path), path.string());
}

gpu::GlRequest library_gl_request(const LfdBridgeSettings& settings) {
  if (const char* env = std::getenv("LFD_GL"); env && *env) return gpu::gl_request_from_env();
  return gpu::parse_gl_request(settings.gl, "gl");
}

void write_lfd_settings(const std::filesystem::path& path, const LfdBridgeSettings& settings) {
  nlohmann::ordered_json root;
  root["calibrations"] = settings.calibrations;
  root["device"] = settings.device;
  root["monitor"] = settings.monitor;
  root["gl"] = settings.gl;
  write_text_atomic(path, root.dump(2) + "\n");
}

}  // namespace lfd::bridge
