// The service: three endpoints over one display service (docs/serve.md).
#include "serve/service.hpp"

#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "serve/bridge_reply.hpp"

namespace lfd::serve {

std::filesystem::path default_state_file() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
    return std::filesystem::path(state) / "lfd" / "serve-playlists.json";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".local" / "state" / "lfd" / "serve-playlists.json";
  return {};
}

std::filesystem::path default_content_folder() {
  if (const char* data = std::getenv("XDG_DATA_HOME"); data && *data)
    return std::filesystem::path(data) / "lfd" / "content";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".local" / "share" / "lfd" / "content";
  return {};
}

Service::Service(DisplayService& displays, ServeOptions options, MemoryBudget* budget)
    : displays_(displays),
      options_(std::move(options)),
      origins_(options_.allowed_origins),
      own_budget_(budget ? nullptr : std::make_unique<MemoryBudget>(options_.limits.memory_budget_bytes)),
      budget_(budget ? *budget : *own_budget_),
      // Named quilts stay until deleted: a quarter of the budget, so they cannot starve shows.
      cache_(options_.limits.memory_budget_bytes / 4, options_.limits.max_cached_quilts),
      decoded_(budget_, options_.limits),
      playlists_(options_.state_file, options_.limits),
      holoplay_(displays_, cache_, decoded_, budget_, options_.limits),
      bridge_(displays_, playlists_, hub_, options_.limits),
      seen_from_(displays_, budget_),
      holoplay_server_(holoplay_, origins_, options_.limits),
      bridge_server_(bridge_, origins_, budget_, options_.limits),
      event_server_(hub_, origins_, budget_, options_.limits) {
  if (!options_.content_folder.empty()) {
    const auto shown = displays_.displays();
    const double aspect = shown.empty() ? 0.75 : shown.front().default_quilt.aspect;
    library_ = std::make_unique<ContentLibrary>(options_.content_folder, options_.limits.max_upload_bytes, aspect);
    thumbnails_ = std::make_unique<LibraryThumbnails>(*library_, budget_);
    console_ = std::make_unique<ConsoleRoutes>(displays_, playlists_, *library_, *thumbnails_, seen_from_, origins_,
                                               options_.listen);
    bridge_server_.set_console(console_.get(), options_.limits.max_upload_bytes);
    origins_.set_console_port(options_.listen.bridge_port);
  }
  if (options_.access_token) origins_.require_token(*options_.access_token);
}

Service::~Service() { stop(); }

void Service::start() {
  // bridge.js's "New Item Playing" handler reads payload.value.playlist_name and .index.
  displays_.set_event_listener([this](const PlaybackEvent& e) {
    const int index = std::max(e.head_index, 0);
    nlohmann::json fields = {{"head_index", wrapped("head_index", "UNSIGNED_INT", index)},
                             {"index", wrapped("index", "UNSIGNED_INT", index)},
                             {"playlist_name", wstring("playlist_name", e.playlist)}};
    hub_.publish(bridge_event(e.name, "", std::move(fields)).dump());
  });
  if (!options_.listen.is_loopback() && !options_.access_token)
    throw std::runtime_error("--listen " + options_.listen.host + ": beyond loopback the service needs its access token");
  holoplay_server_.start(options_.listen);
  bridge_server_.start(options_.listen);
  event_server_.start(options_.listen);
  play_autostart_playlist();
}

void Service::play_autostart_playlist() {
  const auto autostart = playlists_.autostart();
  if (!autostart) return;
  const auto playlist = playlists_.get(autostart->name);
  if (!playlist) {
    spdlog::warn("autostart playlist {}: not among the playlists kept; nothing started", autostart->name);
    return;
  }
  displays_.play_playlist(0, *playlist, autostart->head_index);
  spdlog::info("autostart: playing {} ({} entries)", playlist->name, playlist->entries.size());
}

void Service::stop() {
  displays_.set_event_listener({});
  event_server_.stop();
  bridge_server_.stop();
  holoplay_server_.stop();
}

std::vector<std::string> Service::describe() const {
  const ListenAddress& a = options_.listen;
  std::vector<std::string> lines = {
      fmt::format("HoloPlay Service protocol  ws://{}:{}/driver", a.ws_host(), a.holoplay_port),
      fmt::format("Bridge HTTP API            http://{}:{}/", a.url_host(), a.bridge_port),
      fmt::format("Bridge events              ws://{}:{}/event_source", a.ws_host(), a.events_port),
      a.is_loopback() ? std::string("listening on loopback only: other machines cannot reach it")
                      : fmt::format("listening on {}: OTHER MACHINES CAN REACH IT (--listen)", a.host)};
  std::string origins = "web pages allowed: loopback (localhost, 127.0.0.1, [::1]) and file://";
  for (const auto& o : origins_.extra_origins()) origins += ", " + o;
  lines.push_back(origins + "; every other Origin is refused");
  if (options_.access_token) lines.push_back("every request needs the access token (lfd serve --print-token)");
  if (library_)
    lines.push_back(fmt::format("console                    http://{}:{}/ (content in {})", a.url_host(), a.bridge_port,
                                library_->folder().string()));
  lines.push_back(options_.state_file.empty() ? std::string("playlists kept in memory only")
                                              : "playlists kept in " + options_.state_file.string());
  return lines;
}

std::size_t Service::refused() const {
  return holoplay_server_.refused_connections() + bridge_server_.refused_requests() +
         event_server_.refused_connections();
}

}  // namespace lfd::serve
