// libFuzzer target: format detection and dispatch of load_scene (named .splat so that branch is reachable).
// Any input must either parse or throw lfd::InputError; anything else (a crash, a sanitizer
// report, another exception, an allocation beyond -rss_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scene/scene_parsers.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    lfd::scene::read_scene_bytes(bytes, "fuzz.splat");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
