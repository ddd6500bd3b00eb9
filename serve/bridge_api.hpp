#pragma once
// Bridge's HTTP API (docs/serve.md "Bridge HTTP API", "Sources"): one handler per
// endpoint, each a short function from a parsed body to a reply in Bridge's `{name, type,
// value}` shape. Transport-free: BridgeServer (HTTP) calls `handle`, and so do the tests.
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "serve/display_service.hpp"
#include "serve/memory_budget.hpp"
#include "serve/event_hub.hpp"
#include "serve/playlist_store.hpp"
#include "serve/serve_limits.hpp"

namespace lfd::serve {

// The Bridge version lfd's API answers to (bridge.js wants 2.2 or later for show_window and
// api_version); lfd's own version is in `lfd_status`.
inline constexpr const char* kBridgeApiVersion = "2.5.0.0";
inline constexpr const char* kBridgeApiLevel = "1.4.0";

struct BridgeResponse {
  int http_status = 200;
  std::string body;  // JSON
};

class BridgeApi {
 public:
  BridgeApi(DisplayService& displays, PlaylistStore& playlists, EventHub& events, const ServeLimits& limits);
  // Any endpoint and body; bad input gets an error reply and a log line, never an exception.
  BridgeResponse handle(const std::string& endpoint, std::string_view body);

 private:
  using Handler = std::function<nlohmann::json(const nlohmann::json&)>;
  void add_handlers();
  void add_playlist_handlers();
  void add_transport_handlers();
  std::string orchestration_of(const nlohmann::json& request) const;  // throws when unknown
  std::string new_orchestration();
  nlohmann::json reply(const std::string& endpoint, const nlohmann::json& request, nlohmann::json payload) const;
  void publish(const std::string& event, const std::string& orchestration, nlohmann::json fields = nlohmann::json::object());
  nlohmann::json devices() const;
  // The entry a request describes; with `base`, the fields it leaves out keep base's values
  // (update_playlist_entry) and the uri is optional.
  PlaylistEntry entry_of(const nlohmann::json& request, const PlaylistEntry* base = nullptr) const;
  void add_autostart_handlers();
  // `playlist_name` (one the service keeps) and `head_index` as the autostart playlist.
  nlohmann::json set_autostart(const std::string& endpoint, const nlohmann::json& request);
  // instance_studio_playlist, set_autostart_playlist and sync_overwrite_playlist
  // (bridge_studio_handlers.cpp).
  void add_studio_handlers();
  // Playlist `name` made of the Looking Glass Studio playlist at `path` (replacing any of
  // that name); InputError naming the file and field, nothing changed then.
  void instance_studio_playlist(const std::string& name, const std::string& path, bool loop);

  DisplayService& displays_;
  PlaylistStore& playlists_;
  EventHub& events_;
  const ServeLimits& limits_;
  std::map<std::string, Handler> handlers_;
  mutable std::mutex mutex_;
  std::deque<std::string> orchestrations_;  // the newest last, at most max_connections
};

}  // namespace lfd::serve
