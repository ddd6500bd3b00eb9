// libFuzzer target: `lfd play`'s playlist JSON (play::parse_playlist_json). Any input either
// parses into entries with a file and fields within their bounds, or throws lfd::InputError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "play/playlist.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto playlist = lfd::play::parse_playlist_json(text, "fuzz.json", "/base");
    for (const auto& e : playlist.entries)
      if (e.path.empty() || (e.duration_s && !(*e.duration_s > 0)) || (e.quilt.cols && *e.quilt.cols < 1))
        std::abort();
  } catch (const lfd::InputError&) {
  }
  return 0;
}
