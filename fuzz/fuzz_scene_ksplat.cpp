// libFuzzer target: the .ksplat reader (compression levels 0-2, buckets, SH).
// Any input must either parse or throw lfd::InputError; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scene/scene_parsers.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    lfd::scene::read_ksplat(bytes, "fuzz.ksplat");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
