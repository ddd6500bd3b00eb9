// libFuzzer target: the glTF/GLB reader with KHR_gaussian_splatting (tinygltf, then the
// accessors). The first byte picks the name: odd inputs are read as `.gltf` (JSON), even as
// `.glb`; the reader itself recognises GLB by its magic. Buffers named by URI are looked up
// beside the name, in the fuzzer's working directory. Any input must parse or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scene/scene_parsers.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    lfd::scene::read_gltf(bytes, size && (data[0] & 1) ? "fuzz.gltf" : "fuzz.glb");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
