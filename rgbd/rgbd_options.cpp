#include "rgbd/rgbd_options.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::rgbd {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

// A key in bridge.js's spelling: `depth-loc` and `depth_loc` are the same key.
std::string canonical_key(std::string_view key) {
  std::string out = lower(key);
  std::replace(out.begin(), out.end(), '-', '_');
  return out;
}

void check_range(const std::string& what, const char* field, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi)
    throw_input_error("{}: {} {} must lie in [{}, {}] (bridge.js's range)", what, field, value, lo,
                      hi);
}

double parse_number(std::string_view key, std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end)
    throw_input_error("RGB-D options: {} '{}' is not a number", key, text);
  return value;
}

bool parse_flag(std::string_view key, std::string_view text) {
  const std::string t = lower(text);
  if (t == "1" || t == "true" || t == "yes" || t == "on") return true;
  if (t == "0" || t == "false" || t == "no" || t == "off") return false;
  throw_input_error("RGB-D options: {} '{}' is not 0/1 or true/false", key, text);
}

bool json_flag(const std::string& key, const nlohmann::json& value) {
  if (value.is_boolean()) return value.get<bool>();
  if (value.is_number_integer() || value.is_number_unsigned()) {
    const auto v = value.get<long long>();
    if (v == 0 || v == 1) return v == 1;
  }
  throw_input_error("RGB-D settings: {} must be 0, 1, true or false", key);
}

double json_number(const std::string& key, const nlohmann::json& value) {
  if (!value.is_number()) throw_input_error("RGB-D settings: {} must be a number", key);
  return value.get<double>();
}

// depth_cutoff from a command line: a number, or a flag word (bridge.js 0.0.8-alpha.4's 0/1).
double parse_cutoff(std::string_view key, std::string_view text) {
  const std::string t = lower(text);
  if (t == "true" || t == "yes" || t == "on") return 1.0;
  if (t == "false" || t == "no" || t == "off") return 0.0;
  return parse_number(key, text);
}

constexpr std::array<const char*, 4> kLocationNames = {"top", "bottom", "right", "left"};

}  // namespace

void RgbdOptions::check(const std::string& what) const {
  check_range(what, "depthiness", depthiness, kMinDepthiness, kMaxDepthiness);
  check_range(what, "focus", focus, kMinFocus, kMaxFocus);
  check_range(what, "zoom", zoom, kMinZoom, kMaxZoom);
  check_range(what, "crop_pos_x", crop_pos_x, kMinCropPos, kMaxCropPos);
  check_range(what, "crop_pos_y", crop_pos_y, kMinCropPos, kMaxCropPos);
  check_range(what, "depth_cutoff", depth_cutoff, kMinDepthCutoff, kMaxDepthCutoff);
  const int loc = int(depth_loc);
  if (loc < 0 || loc > 3) throw_input_error("{}: depth_loc {} must be 0..3", what, loc);
}

DepthLocation parse_depth_location(std::string_view text) {
  const std::string t = lower(text);
  for (size_t i = 0; i < kLocationNames.size(); ++i)
    if (t == kLocationNames[i] || t == std::to_string(i)) return DepthLocation(i);
  throw_input_error(
      "RGB-D options: depth_loc '{}' must be top, bottom, right, left or bridge.js's 0..3", text);
}

std::string depth_location_name(DepthLocation location) {
  const int i = int(location);
  return i >= 0 && i < 4 ? kLocationNames[size_t(i)] : "invalid";
}

void set_rgbd_option(RgbdOptions& options, std::string_view key, std::string_view value) {
  const std::string k = canonical_key(key);
  RgbdOptions next = options;
  if (k == "depth_loc") next.depth_loc = parse_depth_location(value);
  else if (k == "depthiness") next.depthiness = parse_number(k, value);
  else if (k == "focus") next.focus = parse_number(k, value);
  else if (k == "depth_inversion") next.depth_inversion = parse_flag(k, value);
  else if (k == "chroma_depth") next.chroma_depth = parse_flag(k, value);
  else if (k == "zoom") next.zoom = parse_number(k, value);
  else if (k == "crop_pos_x") next.crop_pos_x = parse_number(k, value);
  else if (k == "crop_pos_y") next.crop_pos_y = parse_number(k, value);
  else if (k == "depth_cutoff") next.depth_cutoff = parse_cutoff(k, value);
  else throw_input_error("RGB-D options: unknown option '{}'", key);
  next.check("RGB-D options");
  options = next;
}

RgbdOptions rgbd_options_from_json(const nlohmann::json& settings, RgbdOptions base) {
  if (!settings.is_object()) throw_input_error("RGB-D settings: not a JSON object");
  RgbdOptions o = base;
  for (const auto& [key, value] : settings.items()) {
    if (key == "depth_loc") {
      if (value.is_string()) {
        o.depth_loc = parse_depth_location(value.get<std::string>());
      } else if (value.is_number_integer() || value.is_number_unsigned()) {
        const auto v = value.get<long long>();
        if (v < 0 || v > 3) throw_input_error("RGB-D settings: depth_loc {} must be 0..3", v);
        o.depth_loc = DepthLocation(v);
      } else {
        throw_input_error("RGB-D settings: depth_loc must be 0..3 or a side's name");
      }
    } else if (key == "depthiness") o.depthiness = json_number(key, value);
    else if (key == "focus") o.focus = json_number(key, value);
    else if (key == "depth_inversion") o.depth_inversion = json_flag(key, value);
    else if (key == "chroma_depth") o.chroma_depth = json_flag(key, value);
    else if (key == "zoom") o.zoom = json_number(key, value);
    else if (key == "crop_pos_x") o.crop_pos_x = json_number(key, value);
    else if (key == "crop_pos_y") o.crop_pos_y = json_number(key, value);
    else if (key == "depth_cutoff") o.depth_cutoff = value.is_boolean() ? (value.get<bool>() ? 1.0 : 0.0)
                                                                         : json_number(key, value);
  }
  o.check("RGB-D settings");
  return o;
}

RgbdOptions parse_rgbd_options_json(std::string_view text, RgbdOptions base) {
  const nlohmann::json settings = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (settings.is_discarded()) throw_input_error("RGB-D settings: not valid JSON");
  return rgbd_options_from_json(settings, base);
}

nlohmann::json rgbd_options_to_json(const RgbdOptions& options) {
  return {{"depth_loc", int(options.depth_loc)},
          {"depthiness", options.depthiness},
          {"focus", options.focus},
          {"depth_inversion", options.depth_inversion ? 1 : 0},
          {"chroma_depth", options.chroma_depth ? 1 : 0},
          {"zoom", options.zoom},
          {"crop_pos_x", options.crop_pos_x},
          {"crop_pos_y", options.crop_pos_y},
          {"depth_cutoff", options.depth_cutoff}};
}

RgbdOptions rgbd_options_from_command_line(const std::string& settings_path,
                                           const std::vector<std::pair<std::string, std::string>>& flags) {
  RgbdOptions options;
  if (!settings_path.empty()) {
    constexpr std::uintmax_t kMaxSettingsBytes = 1 << 20;  // a settings object is a few hundred bytes
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(settings_path, error);
    if (error) throw_input_error("{}: cannot read the RGB-D settings ({})", settings_path, error.message());
    if (size > kMaxSettingsBytes)
      throw_input_error("{}: {} bytes, more than the {} an RGB-D settings file may have", settings_path, size,
                        kMaxSettingsBytes);
    try {
      options = parse_rgbd_options_json(read_text_file(settings_path));
    } catch (const InputError& e) {
      throw_input_error("{}: {}", settings_path, e.what());
    }
  }
  for (const auto& [key, value] : flags)
    if (!value.empty()) set_rgbd_option(options, key, value);
  return options;
}

}  // namespace lfd::rgbd
