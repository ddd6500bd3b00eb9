// libFuzzer target: a Looking Glass Studio playlist.json and an item's sidecar settings
// (serve::parse_studio_playlist_items, serve::parse_studio_sidecar; docs/serve.md "Studio
// playlists"). Any input must parse or throw lfd::InputError; a parsed item names a relative
// file that stays in the playlist's folder, a parsed sidecar an entry within the service's ranges.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "serve/studio_playlist.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    for (const std::string& name : lfd::serve::parse_studio_playlist_items(text, 1024)) {
      const std::filesystem::path path(name);
      if (name.empty() || path.is_absolute() || path.has_root_directory()) std::abort();
      for (const auto& part : path)
        if (part == "..") std::abort();
    }
  } catch (const lfd::InputError&) {
  }
  try {
    const lfd::serve::PlaylistEntry e = lfd::serve::parse_studio_sidecar(text);
    const auto& q = e.quilt;
    if (q.cols < 1 || q.cols > 100 || q.rows < 1 || q.rows > 100 || q.views < 1 || q.views > q.cols * q.rows)
      std::abort();
    if (!(q.aspect >= 0.01 && q.aspect <= 100) || e.duration_ms < 0 || e.duration_ms > 86'400'000) std::abort();
    if (e.rgbd) {
      try {
        e.rgbd->check();  // a parsed RGB-D entry lies in bridge.js's ranges
      } catch (const lfd::InputError&) {
        std::abort();
      }
    }
  } catch (const lfd::InputError&) {
  }
  return 0;
}
