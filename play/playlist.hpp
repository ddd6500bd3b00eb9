#pragma once
// Playlists for `lfd play` (docs/play.md "Playlists"): the files of the command line, each with
// the same --duration, or a small JSON file:
//   {"loop": true,
//    "entries": [{"file": "scene_qs5x9a1.6.png", "duration": 8},
//                {"file": "clip.mp4", "cols": 8, "rows": 6, "aspect": 0.75}]}
// (a bare array of entries is accepted too). Relative files are relative to the JSON file.
// Entry fields: file (required), duration (seconds, > 0), cols, rows, views, aspect (the tiling
// when the name has none); unknown fields are errors, so a typo does not pass silently.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "play/player.hpp"

namespace lfd::play {

inline constexpr size_t kMaxPlaylistEntries = 10000;
inline constexpr size_t kMaxPlaylistBytes = 4 << 20;

struct Playlist {
  std::vector<PlaylistEntry> entries;
  std::optional<bool> loop;  // when the file says
};

// Parses JSON text; `name` (the file) for messages, `base` for relative paths. InputError
// "NAME: entries[3].duration: ..." naming the field.
Playlist parse_playlist_json(const std::string& text, const std::string& name, const std::filesystem::path& base);
// Reads a playlist file (bounded by kMaxPlaylistBytes).
Playlist read_playlist_json(const std::filesystem::path& path);

// True when `path` names a playlist (.json) rather than a picture or video.
bool is_playlist_file(const std::filesystem::path& path);

}  // namespace lfd::play
