#pragma once
// Bridge's playlists, by name, under the count limits, and the autostart playlist (the one the
// service plays when it starts: Bridge's set_named_autostart_playlist), kept in a state file written atomically
// (util/atomic_file.hpp) after every change and read back at start, so `lfd serve` restarted by
// systemd knows them again. The file's path comes from the service's options, never from a
// request. Thread-safe.
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <map>
#include <vector>

#include "serve/display_service.hpp"
#include "serve/serve_limits.hpp"

namespace lfd::serve {

class PlaylistStore {
 public:
  // `state_file` empty: in memory only.
  PlaylistStore(std::filesystem::path state_file, const ServeLimits& limits);
  void instance(const std::string& name, bool loop);  // a new, empty playlist (replaces)
  // Inserts at `index` (or appends when index < 0 or past the end). Throws InputError.
  void insert(const std::string& name, int index, PlaylistEntry entry);
  // Replaces entry `index` of playlist `name` by what `change` makes of it. Throws InputError
  // for an unknown playlist or index.
  void update(const std::string& name, int index, const std::function<PlaylistEntry(PlaylistEntry)>& change);
  bool erase(const std::string& name);  // the autostart choice stays (a playlist of that name may come again)
  std::optional<Playlist> get(const std::string& name) const;
  std::vector<Playlist> all() const;  // by name
  std::size_t size() const;

  // The playlist to play at start and its first entry (-1: the first), if one was chosen.
  struct Autostart {
    std::string name;
    int head_index = -1;
  };
  void set_autostart(Autostart autostart);
  std::optional<Autostart> autostart() const;

 private:
  void save_locked() const;
  void load();

  std::filesystem::path file_;
  const ServeLimits& limits_;
  mutable std::mutex mutex_;
  std::map<std::string, Playlist> playlists_;
  std::optional<Autostart> autostart_;
};

}  // namespace lfd::serve
