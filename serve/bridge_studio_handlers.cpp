// Bridge's endpoints for Looking Glass Studio playlists and for syncing a playlist to the
// display (docs/serve.md "Studio playlists", "sync_overwrite_playlist").
#include "serve/bridge_api.hpp"
#include "serve/bridge_reply.hpp"
#include "serve/bridge_request.hpp"
#include "serve/studio_playlist.hpp"
#include "util/error.hpp"

namespace lfd::serve {

using json = nlohmann::json;

void BridgeApi::instance_studio_playlist(const std::string& name, const std::string& path, bool loop) {
  if (name.empty()) throw_input_error("name: missing");
  // Read and checked in full before the store changes: a bad file leaves the playlists alone.
  const std::vector<PlaylistEntry> entries = read_studio_playlist(path, limits_.max_playlist_entries, limits_.max_file_bytes);
  playlists_.instance(name, loop);
  for (const PlaylistEntry& e : entries) playlists_.insert(name, -1, e);
}

void BridgeApi::add_studio_handlers() {
  // bridge.js's playStudioPlaylist: {name: "Studio Playlist", playlist_path, loop}, then
  // play_playlist of that name.
  handlers_["instance_studio_playlist"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const std::string name = field_text(r, "name", limits_.max_name_chars, "");
    instance_studio_playlist(name, field_text(r, "playlist_path", 4096, ""), field_bool(r, "loop", true));
    publish("Playlist Instance", token, {{"name", wstring("name", name)}});
    return reply("instance_studio_playlist", r, wrapped("value", "VARIANT_MAP", {{"name", wstring("name", name)}}));
  };
  // Bridge's menu "Set AutoStart Playlist" takes a Studio playlist.json; bridge.js's
  // setAutoStartPlaylist sends its path with a name. Without a path, the named playlist of this
  // service (as set_named_autostart_playlist).
  handlers_["set_autostart_playlist"] = [this](const json& r) {
    orchestration_of(r);
    const std::string path = field_text(r, "playlist_path", 4096, "");
    if (!path.empty()) instance_studio_playlist(field_text(r, "playlist_name", limits_.max_name_chars, ""), path, true);
    return set_autostart("set_autostart_playlist", r);
  };
  // The vendor's Toolkit (LKG-Toolkit TrySyncPlaylist) sends {name, head_index, crf,
  // pixel_format, encoder}: Bridge encodes the playlist and overwrites the one a Looking Glass
  // Go keeps in its own storage and plays on its own. lfd's displays keep nothing: the service
  // is what plays on its own, so the playlist becomes the one it plays at every start (the
  // autostart, in the state file, replacing the previous) and plays now. Its files play as they
  // are; the encoder settings are checked, not used (docs/serve.md).
  handlers_["sync_overwrite_playlist"] = [this](const json& r) {
    const std::string token = orchestration_of(r);
    const std::string name = field_text(r, "name", limits_.max_name_chars, "");
    const auto playlist = playlists_.get(name);
    if (!playlist) throw_input_error("name: no playlist named {}", name);
    const int head = field_int(r, "head_index", -1, limits_.max_playlist_entries, -1);
    field_int(r, "crf", 0, 63, 20);
    field_text(r, "pixel_format", 32, "");
    field_text(r, "encoder", 32, "");
    publish("Sync/Play Playlist", token, {{"name", wstring("name", name)}});
    playlists_.set_autostart({name, head});
    displays_.play_playlist(0, *playlist, head);
    publish("Sync/Play Playlist Complete", token, {{"name", wstring("name", name)}});
    return reply("sync_overwrite_playlist", r, wrapped("value", "VARIANT_MAP", {{"name", wstring("name", name)}}));
  };
}

}  // namespace lfd::serve
