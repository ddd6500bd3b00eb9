// Reading Looking Glass Studio playlists (docs/serve.md "Studio playlists").
#include "serve/studio_playlist.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "rgbd/rgbd_options.hpp"
#include "serve/bridge_request.hpp"
#include "serve/request_file.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::serve {

namespace {

constexpr std::size_t kMaxFileNameChars = 1024;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

// A file beside the playlist: relative, no `..`, no NUL, nothing that leaves its folder.
void check_file_name(const std::string& name, std::size_t item) {
  if (name.empty()) throw_input_error("item {}: filename is empty", item);
  if (name.find('\0') != std::string::npos) throw_input_error("item {}: filename has a NUL byte", item);
  const std::filesystem::path path(name);
  if (path.is_absolute() || path.has_root_name() || path.has_root_directory())
    throw_input_error("item {}: filename {} is not relative to the playlist", item, name);
  for (const auto& part : path)
    if (part == "..") throw_input_error("item {}: filename {} leaves the playlist's folder", item, name);
}

// depthPosition as a side's name or bridge.js's number.
rgbd::DepthLocation depth_position(const nlohmann::json& sidecar) {
  const auto it = sidecar.find("depthPosition");
  if (it == sidecar.end() || it->is_null()) return rgbd::RgbdOptions{}.depth_loc;
  if (it->is_string()) return rgbd::parse_depth_location(it->get<std::string>());
  if (it->is_number_integer() || it->is_number_unsigned()) return rgbd::parse_depth_location(it->dump());
  throw_input_error("depthPosition: not a side's name or 0..3");
}

// Throws InputError "<what>: <reason>" for whatever `f` throws as InputError.
template <typename F>
auto naming(const std::string& what, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw_input_error("{}: {}", what, e.what());
  }
}

}  // namespace

std::vector<std::string> parse_studio_playlist_items(std::string_view text, int max_entries) {
  const nlohmann::json items = parse_bounded_json(text, kMaxStudioPlaylistBytes, "playlist");
  if (!items.is_array()) throw_input_error("playlist: not a JSON array of items");
  if (items.size() > std::size_t(std::max(max_entries, 0)))
    throw_input_error("playlist: {} items, more than the {} a playlist may have", items.size(), max_entries);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!items[i].is_object()) throw_input_error("item {}: not an object", i);
    const std::string name = naming(fmt::format("item {}", i), [&] {
      return field_text(items[i], "filename", kMaxFileNameChars, "");
    });
    check_file_name(name, i);
    names.push_back(name);
  }
  return names;
}

PlaylistEntry parse_studio_sidecar(std::string_view text) {
  const nlohmann::json s = parse_bounded_json(text, kMaxStudioSidecarBytes, "sidecar");
  if (!s.is_object()) throw_input_error("sidecar: not a JSON object");
  PlaylistEntry e{{}, std::nullopt, {1, 1, 1, 1.0}, 0, 0};
  const std::string type = lower(field_text(s, "mediaType", 64, ""));
  if (type != "quilt" && type != "rgbd")
    throw_input_error("mediaType: '{}' is neither quilt nor rgbd", type);
  static const nlohmann::json kNone = nlohmann::json::object();
  const nlohmann::json& q = s.contains("quilt_settings") && !s["quilt_settings"].is_null() ? s["quilt_settings"] : kNone;
  if (!q.is_object()) throw_input_error("quilt_settings: not an object");
  if (type == "quilt" && q.empty()) throw_input_error("quilt_settings: missing for a quilt");
  naming("quilt_settings", [&] {
    e.quilt.cols = field_int(q, "viewX", 1, 100, 1);
    e.quilt.rows = field_int(q, "viewY", 1, 100, 1);
    e.quilt.views = field_int(q, "viewTotal", 1, e.quilt.cols * e.quilt.rows, e.quilt.cols * e.quilt.rows);
    e.quilt.aspect = field_number(q, "aspect", 0.01, 100, 1.0);
    // lfd's quilts keep Looking Glass's view order (view 0 bottom-left); a reversed one is
    // refused rather than shown mirrored in depth.
    if (field_bool(q, "invertViews", false)) throw_input_error("invertViews: reversed view order is not supported");
    return 0;
  });
  if (field_bool(s, "viewOrderReversed", false))
    throw_input_error("viewOrderReversed: reversed view order is not supported");
  e.focus = field_number(s, "focus", -10, 10, 0);
  if (type == "quilt" && field_number(s, "zoom", -1e6, 1e6, 1) != 1)
    throw_input_error("zoom: a quilt's zoom other than 1 is not supported");
  e.duration_ms = int(std::lround(field_number(s, "duration", 0, 86'400, 0) * 1000));
  if (type == "rgbd") {
    rgbd::RgbdOptions o;
    o.depth_loc = depth_position(s);
    o.depthiness = field_number(s, "depthiness", -1e6, 1e6, o.depthiness);
    o.focus = field_number(s, "focus", -1e6, 1e6, o.focus);
    o.depth_inversion = field_bool(s, "depthInversion", o.depth_inversion);
    o.chroma_depth = field_bool(s, "chromaDepth", o.chroma_depth);
    o.zoom = field_number(s, "zoom", -1e6, 1e6, o.zoom);
    o.crop_pos_x = field_number(s, "position_x", -1e6, 1e6, o.crop_pos_x);
    o.crop_pos_y = field_number(s, "position_y", -1e6, 1e6, o.crop_pos_y);
    o.depth_cutoff = field_number(s, "depth_cutoff", -1e6, 1e6, o.depth_cutoff);
    o.check("sidecar");
    e.rgbd = o;
    e.focus = 0;  // an RGB-D entry's focus is its options' (docs/rgbd.md)
  }
  return e;
}

std::vector<PlaylistEntry> read_studio_playlist(const std::string& uri, int max_entries, std::size_t max_file_bytes) {
  const std::filesystem::path playlist = checked_request_file(uri, kMaxStudioPlaylistBytes);
  const std::vector<std::string> names =
      naming(playlist.string(), [&] { return parse_studio_playlist_items(read_text_file(playlist), max_entries); });
  std::vector<PlaylistEntry> entries;
  for (const std::string& name : names) {
    const std::filesystem::path media = playlist.parent_path() / name;
    std::filesystem::path sidecar = media;
    sidecar += ".json";
    checked_request_file(sidecar.string(), kMaxStudioSidecarBytes);
    PlaylistEntry e = naming(sidecar.string(), [&] { return parse_studio_sidecar(read_text_file(sidecar)); });
    e.file = checked_request_file(media.string(), max_file_bytes);
    entries.push_back(std::move(e));
  }
  return entries;
}

}  // namespace lfd::serve
