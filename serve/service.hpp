#pragma once
// The whole service (docs/serve.md): the HoloPlay endpoint, Bridge's HTTP API and its event
// socket over one DisplayService, with one Origin policy and one set of limits.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "serve/bridge_api.hpp"
#include "serve/bridge_server.hpp"
#include "serve/console_routes.hpp"
#include "serve/content_library.hpp"
#include "serve/event_hub.hpp"
#include "serve/event_server.hpp"
#include "serve/decoded_quilts.hpp"
#include "serve/holoplay_protocol.hpp"
#include "serve/holoplay_server.hpp"
#include "serve/listen_address.hpp"
#include "serve/memory_budget.hpp"
#include "serve/origin_policy.hpp"
#include "serve/playlist_store.hpp"
#include "serve/quilt_cache.hpp"
#include "serve/seen_from.hpp"

namespace lfd::serve {

struct ServeOptions {
  ListenAddress listen;
  std::vector<std::string> allowed_origins;  // --allow-origin
  std::filesystem::path state_file;          // playlists; empty: in memory only
  ServeLimits limits;
  // The console's content folder (docs/console.md); empty: no console, GET / as Bridge's.
  std::filesystem::path content_folder;
  // Needed by every request when listening beyond loopback (access_token.hpp): start() refuses
  // a non-loopback address without one.
  std::optional<AccessToken> access_token;
};

// $XDG_DATA_HOME/lfd/content (or ~/.local/share/lfd/content); empty when neither is set.
std::filesystem::path default_content_folder();

// $XDG_STATE_HOME/lfd/serve-playlists.json (or ~/.local/state/...); empty when neither is set.
std::filesystem::path default_state_file();

class Service {
 public:
  // `budget`: the one the display service reserves from too (apps/serve.cpp); none: the
  // service's own, of options.limits.memory_budget_bytes.
  Service(DisplayService& displays, ServeOptions options, MemoryBudget* budget = nullptr);
  ~Service();
  // Listens, then plays the autostart playlist if one was chosen (set_named_autostart_playlist).
  // Throws std::runtime_error naming the address it cannot listen on.
  void start();
  void stop();
  // What it listens on and who may talk to it, one line each (printed at start).
  std::vector<std::string> describe() const;
  EventHub& events() { return hub_; }
  MemoryBudget& budget() { return budget_; }
  std::size_t refused() const;

 private:
  void play_autostart_playlist();

  DisplayService& displays_;
  ServeOptions options_;
  OriginPolicy origins_;
  std::unique_ptr<MemoryBudget> own_budget_;
  MemoryBudget& budget_;
  QuiltCache cache_;
  DecodedQuilts decoded_;
  PlaylistStore playlists_;
  EventHub hub_;
  HoloPlayProtocol holoplay_;
  BridgeApi bridge_;
  std::unique_ptr<ContentLibrary> library_;
  std::unique_ptr<LibraryThumbnails> thumbnails_;
  SeenFromRenderer seen_from_;
  std::unique_ptr<ConsoleRoutes> console_;
  HoloPlayServer holoplay_server_;
  BridgeServer bridge_server_;
  EventServer event_server_;
};

}  // namespace lfd::serve
