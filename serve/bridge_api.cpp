// Bridge's HTTP API endpoints (docs/serve.md, "Bridge HTTP API").
#include "serve/bridge_api.hpp"

#include <unistd.h>

#include <algorithm>
#include <random>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "serve/bridge_reply.hpp"
#include "serve/bridge_request.hpp"
#include "serve/request_file.hpp"
#include "serve/served_display_json.hpp"
#include "util/error.hpp"
#include "util/version.hpp"

namespace lfd::serve {

using json = nlohmann::json;

namespace {

// An orchestration the service does not know: the reply's status says so (HTTP 200, as Bridge).
struct UnknownOrchestration : InputError {
  using InputError::InputError;
};

}  // namespace

BridgeApi::BridgeApi(DisplayService& displays, PlaylistStore& playlists, EventHub& events, const ServeLimits& limits)
    : displays_(displays), playlists_(playlists), events_(events), limits_(limits) {
  add_handlers();
  add_playlist_handlers();
  add_transport_handlers();
  add_autostart_handlers();
  add_studio_handlers();
}

BridgeResponse BridgeApi::handle(const std::string& endpoint, std::string_view body) {
  const auto it = handlers_.find(endpoint);
  if (it == handlers_.end()) {
    spdlog::warn("bridge: unknown endpoint {}", endpoint.substr(0, 64));
    return {404, bridge_reply(endpoint.substr(0, 64), "", wstring("value", "unknown endpoint"), "Failure").dump()};
  }
  try {
    const json request = parse_bridge_request(body, limits_.max_body_bytes);
    return {200, it->second(request).dump()};
  } catch (const BusyError& e) {  // not logged: a line per refusal under load (docs/serve.md "Memory")
    return {503, bridge_reply(endpoint, "", wstring("value", e.what()), "Failure").dump()};
  } catch (const UnknownOrchestration& e) {
    spdlog::warn("bridge {}: {}", endpoint, e.what());
    return {200, bridge_reply(endpoint, "", wstring("value", e.what()), "UnknownOrchestration").dump()};
  } catch (const InputError& e) {
    spdlog::warn("bridge {}: {}", endpoint, e.what());
    return {400, bridge_reply(endpoint, "", wstring("value", e.what()), "Failure").dump()};
  } catch (const std::exception& e) {
    spdlog::error("bridge {}: {}", endpoint, e.what());
    return {500, bridge_reply(endpoint, "", wstring("value", e.what()), "Failure").dump()};
  }
}

std::string BridgeApi::new_orchestration() {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  const std::string token = fmt::format("{:016x}{:016x}", random(), random());
  std::lock_guard lock(mutex_);
  orchestrations_.push_back(token);
  while (static_cast<int>(orchestrations_.size()) > limits_.max_connections) orchestrations_.pop_front();
  return token;
}

std::string BridgeApi::orchestration_of(const json& request) const {
  const std::string token = field_text(request, "orchestration", 128, "");
  std::lock_guard lock(mutex_);
  if (std::find(orchestrations_.begin(), orchestrations_.end(), token) == orchestrations_.end())
    throw UnknownOrchestration("orchestration: not one this service gave out (enter_orchestration first)");
  return token;
}

json BridgeApi::reply(const std::string& endpoint, const json& request, json payload) const {
  return bridge_reply(endpoint, field_text(request, "orchestration", 128, ""), std::move(payload));
}

void BridgeApi::publish(const std::string& event, const std::string& orchestration, json fields) {
  events_.publish(bridge_event(event, orchestration, std::move(fields)).dump());
}

json BridgeApi::devices() const {
  json out = json::object();
  for (const ServedDisplay& d : displays_.displays()) {
    const std::string key = std::to_string(d.index);
    out[key] = wrapped(key, "VARIANT_MAP",
                       {{"calibration", wstring("calibration", served_calibration(d).dump())},
                        {"defaultQuilt", wstring("defaultQuilt", served_default_quilt(d).dump())},
                        {"hardwareVersion", wstring("hardwareVersion", d.hardware_version)},
                        {"hwid", wstring("hwid", d.hwid)},
                        {"index", wrapped("index", "UNSIGNED_INT", d.index)},
                        {"state", wstring("state", "ok")},
                        {"windowCoords", wrapped("windowCoords", "INT2", {{"x", d.window_x}, {"y", d.window_y}})},
                        {"calibrationSource", wstring("calibrationSource", d.calibration_source)}});
  }
  return out;
}

void BridgeApi::add_handlers() {
  handlers_["bridge_version"] = [this](const json& r) {
    return reply("bridge_version", r, wstring("value", kBridgeApiVersion));
  };
  handlers_["api_version"] = [this](const json& r) {
    return reply("api_version", r, wstring("value", kBridgeApiLevel));
  };
  handlers_["enter_orchestration"] = [this](const json& r) {
    field_text(r, "name", limits_.max_name_chars, "default");
    const std::string token = new_orchestration();
    return bridge_reply("enter_orchestration", token, wstring("value", token));
  };
  handlers_["exit_orchestration"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    std::lock_guard lock(mutex_);
    orchestrations_.erase(std::find(orchestrations_.begin(), orchestrations_.end(), token));
    return bridge_reply("exit_orchestration", token, nullptr);
  };
  handlers_["available_output_devices"] = [this](const json& r) {
    orchestration_of(r);
    return reply("available_output_devices", r, wrapped("value", "VARIANT_MAP", devices()));
  };
  handlers_["show_window"] = [this](const json& r) {
    orchestration_of(r);
    displays_.show_window(field_bool(r, "show_window", true));
    return reply("show_window", r, nullptr);
  };
  // lfd's own: what the service shows (`lfd serve --status`).
  handlers_["lfd_status"] = [this](const json& r) {
    const PlaybackState s = displays_.state();
    json displays = json::array();
    for (const ServedDisplay& d : displays_.displays())
      displays.push_back({{"index", d.index}, {"hwid", d.hwid}, {"calibration", d.calibration_path.string()},
                          {"calibration_source", d.calibration_source}});
    return reply("lfd_status", r,
                 wrapped("value", "VARIANT_MAP",
                         {{"version", lfd::version_info().version}, {"pid", static_cast<int>(::getpid())}, {"showing", s.showing}, {"playlist", s.playlist},
                          {"index", s.index}, {"entries", s.entries}, {"playing", s.playing}, {"window_visible", s.window_visible},
                          {"quilt_aspect", s.quilt_aspect}, {"position_s", s.position_s},
                          {"duration_s", s.duration_s}, {"is_video", s.is_video},
                          {"rgbd", s.rgbd ? rgbd::rgbd_options_to_json(*s.rgbd) : json(nullptr)},
                          {"displays", displays}}));
  };
}

namespace {

// An RGB-D entry's keys (depth_loc, depthiness, focus, ...) read by the RGB-D module's one
// parser, which knows bridge.js's ranges and defaults; bridge.js sends some values as text.
rgbd::RgbdOptions rgbd_options_of(const json& r, rgbd::RgbdOptions o = {}) {
  for (const char* key : {"depth_loc", "depthiness", "focus", "depth_inversion", "chroma_depth", "zoom",
                          "crop_pos_x", "crop_pos_y", "depth_cutoff"}) {
    if (!r.contains(key)) continue;
    const json& v = r.at(key);
    if (v.is_string())
      rgbd::set_rgbd_option(o, key, v.get<std::string>());
    else if (v.is_number() || v.is_boolean())
      rgbd::set_rgbd_option(o, key, v.is_boolean() ? (v.get<bool>() ? "1" : "0") : v.dump());
    else
      throw_input_error("{}: not a number", key);
  }
  return o;
}

}  // namespace

PlaylistEntry BridgeApi::entry_of(const json& r, const PlaylistEntry* base) const {
  PlaylistEntry e = base ? *base : PlaylistEntry{{}, std::nullopt, {1, 1, 1, 1.0}, 0, 0};
  if (!base || r.contains("uri")) e.file = checked_request_file(field_text(r, "uri", 4096, ""), limits_.max_file_bytes);
  e.quilt.cols = field_int(r, "cols", 1, 100, e.quilt.cols);
  e.quilt.rows = field_int(r, "rows", 1, 100, e.quilt.rows);
  const int tiles = e.quilt.cols * e.quilt.rows;
  e.quilt.views = field_int(r, "view_count", 1, tiles, base && e.quilt.views <= tiles ? e.quilt.views : tiles);
  e.quilt.aspect = field_number(r, "aspect", 0.01, 100, e.quilt.aspect);
  e.focus = field_number(r, "focus", -10, 10, e.focus);
  e.duration_ms = field_int(r, "durationMS", 0, 86'400'000, e.duration_ms);
  if (field_bool(r, "isRGBD", e.rgbd.has_value())) e.rgbd = rgbd_options_of(r, e.rgbd.value_or(rgbd::RgbdOptions{}));
  else e.rgbd.reset();
  return e;
}

void BridgeApi::add_playlist_handlers() {
  handlers_["instance_playlist"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const std::string name = field_text(r, "name", limits_.max_name_chars, "");
    if (name.empty()) throw_input_error("name: missing");
    playlists_.instance(name, field_bool(r, "loop", true));
    publish("Playlist Instance", token, {{"name", wstring("name", name)}});
    return reply("instance_playlist", r, wrapped("value", "VARIANT_MAP", {{"name", wstring("name", name)}}));
  };
  handlers_["insert_playlist_entry"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const std::string name = field_text(r, "name", limits_.max_name_chars, "");
    const int index = field_int(r, "index", -1, limits_.max_playlist_entries, -1);
    playlists_.insert(name, index, entry_of(r));
    publish("Playlist Insert", token, {{"name", wstring("name", name)}});
    return reply("insert_playlist_entry", r,
                 wrapped("value", "VARIANT_MAP", {{"index", wstring("index", std::to_string(index))}}));
  };
  handlers_["play_playlist"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const std::string name = field_text(r, "name", limits_.max_name_chars, "");
    const auto playlist = playlists_.get(name);
    if (!playlist) throw_input_error("name: no playlist named {}", name);
    const int head = field_int(r, "head_index", -1, limits_.max_playlist_entries, -1);
    displays_.play_playlist(0, *playlist, head);
    publish("Sync/Play Playlist", token, {{"name", wstring("name", name)}});
    return reply("play_playlist", r, wrapped("value", "VARIANT_MAP", {{"name", wstring("name", name)}}));
  };
  handlers_["delete_playlist"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const std::string name = field_text(r, "name", limits_.max_name_chars, "");
    if (!playlists_.erase(name)) throw_input_error("name: no playlist named {}", name);
    displays_.stop_playlist(name);
    publish("Playlist Delete", token, {{"name", wstring("name", name)}});
    return reply("delete_playlist", r, wrapped("value", "VARIANT_MAP", {{"name", wstring("name", name)}}));
  };
  // bridge.js's schema: playlistName, playlistIndex and the entry's fields to change.
  handlers_["update_playlist_entry"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const std::string name = field_text(r, "playlistName", limits_.max_name_chars, field_text(r, "name", limits_.max_name_chars, ""));
    const int index = field_int(r, "playlistIndex", 0, limits_.max_playlist_entries, field_int(r, "index", 0, limits_.max_playlist_entries, 0));
    playlists_.update(name, index, [&](PlaylistEntry old) { return entry_of(r, &old); });
    // The playlist on screen plays again from the entry shown, with the change.
    const PlaybackState state = displays_.state();
    if (state.playlist == name)
      if (const auto playlist = playlists_.get(name)) displays_.play_playlist(0, *playlist, std::max(state.index, 0));
    publish("Playlist Update", token, {{"name", wstring("name", name)}});
    return reply("update_playlist_entry", r, nullptr);
  };
  handlers_["update_current_entry"] = [this](const json& r) {
    orchestration_of(r);
    int updated = 0;
    for (const char* key : {"focus", "depthiness", "zoom", "crop_pos_x", "crop_pos_y", "aspect", "depth_cutoff"}) {
      if (!r.contains(key)) continue;
      displays_.update_current_entry(key, field_number(r, key, -100, 100, 0));
      ++updated;
    }
    if (updated == 0) throw_input_error("update_current_entry: no parameter this service knows");
    return reply("update_current_entry", r, nullptr);
  };
}

// The playlist the service plays when it starts (Service::start), kept in the state file.
void BridgeApi::add_autostart_handlers() {
  handlers_["get_autostart_playlist"] = [this](const json& r) {
    orchestration_of(r);
    const auto autostart = playlists_.autostart();
    return reply("get_autostart_playlist", r,
                 wrapped("value", "VARIANT_MAP",
                         {{"playlist_name", wstring("playlist_name", autostart ? autostart->name : "")},
                          {"playlist_path", wstring("playlist_path", "")}}));
  };
  handlers_["set_named_autostart_playlist"] = [this](const json& r) {
    return set_autostart("set_named_autostart_playlist", r);
  };
}

json BridgeApi::set_autostart(const std::string& endpoint, const json& r) {
  orchestration_of(r);
  const std::string name = field_text(r, "playlist_name", limits_.max_name_chars, "");
  if (!playlists_.get(name)) throw_input_error("playlist_name: no playlist named {}", name);
  playlists_.set_autostart({name, field_int(r, "head_index", -1, limits_.max_playlist_entries, -1)});
  return reply(endpoint, r, wrapped("value", "VARIANT_MAP", {{"playlist_name", wstring("playlist_name", name)}}));
}

void BridgeApi::add_transport_handlers() {
  const std::pair<const char*, Transport> simple[] = {
      {"play", Transport::kPlay}, {"pause", Transport::kPause}, {"next", Transport::kNext},
      {"previous", Transport::kPrevious}};
  const std::map<std::string, std::string> event_names = {
      {"play", "Transport Control Play"}, {"pause", "Transport Control Pause"},
      {"next", "Transport Control Next"}, {"previous", "Transport Control Previous"}};
  for (const auto& [verb, command] : simple) {
    const std::string endpoint = std::string("transport_control_") + verb;
    const std::string event = event_names.at(verb);
    handlers_[endpoint] = [this, endpoint, event, command = command](const json& r) {
      const std::string token = orchestration_of(r);
      displays_.transport(command, -1);
      publish(event, token);
      return reply(endpoint, r, nullptr);
    };
  }
  // lfd's own: a position within the entry shown (a video's frame at that time; Bridge seeks
  // only between entries). The event tells the pages to read the state again.
  handlers_["lfd_seek"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const double seconds = field_number(r, "seconds", 0, 7 * 24 * 3600.0, -1);
    if (seconds < 0) throw_input_error("seconds: missing");
    displays_.seek(seconds);
    publish("lfd Transport Seek", token);
    return reply("lfd_seek", r, nullptr);
  };
  handlers_["transport_control_seek_to_index"] = [this](const json& r) {
    orchestration_of(r);
    displays_.transport(Transport::kSeekToIndex, field_int(r, "index", 0, limits_.max_playlist_entries, 0));
    return reply("transport_control_seek_to_index", r, nullptr);
  };
}

}  // namespace lfd::serve
