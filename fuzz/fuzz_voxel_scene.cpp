// libFuzzer target: the sparse-voxel readers (.voxels and the svraster-webgl PLY) behind their
// dispatch. Any input must either parse or throw lfd::InputError; anything else (a crash, a
// sanitizer report, another exception, an allocation beyond -rss_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "util/error.hpp"
#include "scene/voxel_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    lfd::scene::read_voxel_scene_bytes(bytes, "fuzz.voxels");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
