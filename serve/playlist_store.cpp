// Playlists and their state file (docs/serve.md, "State").
#include "serve/playlist_store.hpp"

#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "rgbd/rgbd_options.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::serve {

using json = nlohmann::json;

namespace {

json entry_json(const PlaylistEntry& e) {
  return {{"file", e.file.string()}, {"cols", e.quilt.cols}, {"rows", e.quilt.rows},
          {"views", e.quilt.views}, {"aspect", e.quilt.aspect}, {"focus", e.focus},
          {"duration_ms", e.duration_ms},
          {"rgbd", e.rgbd ? rgbd::rgbd_options_to_json(*e.rgbd) : json(nullptr)}};
}

PlaylistEntry entry_from_json(const json& j) {
  PlaylistEntry e;
  e.file = j.at("file").get<std::string>();
  if (!j.at("rgbd").is_null()) e.rgbd = rgbd::rgbd_options_from_json(j.at("rgbd"));
  e.quilt = {j.at("cols").get<int>(), j.at("rows").get<int>(), j.at("views").get<int>(), j.at("aspect").get<double>()};
  e.focus = j.at("focus").get<double>();
  e.duration_ms = j.at("duration_ms").get<int>();
  return e;
}

}  // namespace

PlaylistStore::PlaylistStore(std::filesystem::path state_file, const ServeLimits& limits)
    : file_(std::move(state_file)), limits_(limits) {
  if (!file_.empty() && std::filesystem::exists(file_)) load();
}

void PlaylistStore::load() {
  try {
    const json root = json::parse(read_text_file(file_));
    for (const auto& [name, p] : root.at("playlists").items()) {
      if (static_cast<int>(playlists_.size()) >= limits_.max_playlists) break;
      Playlist playlist{name, p.at("loop").get<bool>(), {}};
      for (const auto& e : p.at("entries")) playlist.entries.push_back(entry_from_json(e));
      playlists_[name] = std::move(playlist);
    }
    if (root.contains("autostart") && !root.at("autostart").is_null())
      autostart_ = Autostart{root.at("autostart").at("name").get<std::string>(),
                             root.at("autostart").at("head_index").get<int>()};
  } catch (const std::exception& e) {
    spdlog::warn("{}: not read, starting without playlists ({})", file_.string(), e.what());
    playlists_.clear();
  }
}

void PlaylistStore::save_locked() const {
  if (file_.empty()) return;
  json root = {{"format", "lfd-serve-playlists"}, {"version", 1}, {"playlists", json::object()}};
  for (const auto& [name, p] : playlists_) {
    json entries = json::array();
    for (const auto& e : p.entries) entries.push_back(entry_json(e));
    root["playlists"][name] = {{"loop", p.loop}, {"entries", entries}};
  }
  root["autostart"] = autostart_ ? json{{"name", autostart_->name}, {"head_index", autostart_->head_index}} : json(nullptr);
  write_text_atomic(file_, root.dump(1));
}

void PlaylistStore::instance(const std::string& name, bool loop) {
  std::lock_guard lock(mutex_);
  if (!playlists_.count(name) && static_cast<int>(playlists_.size()) >= limits_.max_playlists)
    throw_input_error("name: {} playlists is the limit", limits_.max_playlists);
  playlists_[name] = Playlist{name, loop, {}};
  save_locked();
}

void PlaylistStore::insert(const std::string& name, int index, PlaylistEntry entry) {
  std::lock_guard lock(mutex_);
  auto it = playlists_.find(name);
  if (it == playlists_.end()) throw_input_error("name: no playlist named {}", name);
  auto& entries = it->second.entries;
  if (static_cast<int>(entries.size()) >= limits_.max_playlist_entries)
    throw_input_error("name: {} entries is the limit of a playlist", limits_.max_playlist_entries);
  if (index < 0 || index >= static_cast<int>(entries.size())) entries.push_back(std::move(entry));
  else entries.insert(entries.begin() + index, std::move(entry));
  save_locked();
}

void PlaylistStore::update(const std::string& name, int index,
                           const std::function<PlaylistEntry(PlaylistEntry)>& change) {
  std::lock_guard lock(mutex_);
  auto it = playlists_.find(name);
  if (it == playlists_.end()) throw_input_error("playlistName: no playlist named {}", name);
  auto& entries = it->second.entries;
  if (index < 0 || index >= static_cast<int>(entries.size()))
    throw_input_error("playlistIndex: {} is not an entry of {} ({} entries)", index, name, entries.size());
  entries[index] = change(entries[index]);
  save_locked();
}

void PlaylistStore::set_autostart(Autostart autostart) {
  std::lock_guard lock(mutex_);
  autostart_ = std::move(autostart);
  save_locked();
}

std::optional<PlaylistStore::Autostart> PlaylistStore::autostart() const {
  std::lock_guard lock(mutex_);
  return autostart_;
}

bool PlaylistStore::erase(const std::string& name) {
  std::lock_guard lock(mutex_);
  if (!playlists_.erase(name)) return false;
  save_locked();
  return true;
}

std::vector<Playlist> PlaylistStore::all() const {
  std::lock_guard lock(mutex_);
  std::vector<Playlist> out;
  for (const auto& [name, playlist] : playlists_) out.push_back(playlist);
  return out;
}

std::optional<Playlist> PlaylistStore::get(const std::string& name) const {
  std::lock_guard lock(mutex_);
  const auto it = playlists_.find(name);
  if (it == playlists_.end()) return std::nullopt;
  return it->second;
}

std::size_t PlaylistStore::size() const {
  std::lock_guard lock(mutex_);
  return playlists_.size();
}

}  // namespace lfd::serve
