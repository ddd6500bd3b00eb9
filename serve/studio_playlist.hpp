#pragma once
// A Looking Glass Studio playlist, as bridge.js's playStudioPlaylist hands its path to
// `instance_studio_playlist` (docs/serve.md "Studio playlists"): `playlist.json` is a JSON array
// of items `{"filename": ..., "last_updated": ..., "needs_sync": ...}`, and each item's media
// file sits beside it with a "sidecar" `<filename>.json` holding its settings (`mediaType`,
// `quilt_settings` {viewX, viewY, viewTotal, aspect, invertViews}, `focus`, `zoom`, `duration`
// in seconds, and the RGB-D keys depthiness, depthInversion, chromaDepth, depthPosition,
// position_x, position_y). Only files are read, through the service's file rule
// (serve/request_file.hpp), each under a size limit; nothing is written.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "serve/display_service.hpp"

namespace lfd::serve {

inline constexpr std::size_t kMaxStudioPlaylistBytes = 1u << 20;  // a list of file names
inline constexpr std::size_t kMaxStudioSidecarBytes = 64u << 10;  // a settings object

// The items' file names of playlist.json's text, in order; at most `max_entries`. Each is a
// relative path without `..` (it names a file beside the playlist). InputError naming the item
// and field.
std::vector<std::string> parse_studio_playlist_items(std::string_view text, int max_entries);

// One item's sidecar text as a playlist entry (its `file` left empty). InputError naming the
// field.
PlaylistEntry parse_studio_sidecar(std::string_view text);

// The entries of the Studio playlist at `uri` (a request's uri: file:// or an absolute path),
// each item's file and sidecar read beside it under the file rule and `max_file_bytes`.
// InputError naming the file and field.
std::vector<PlaylistEntry> read_studio_playlist(const std::string& uri, int max_entries, std::size_t max_file_bytes);

}  // namespace lfd::serve
