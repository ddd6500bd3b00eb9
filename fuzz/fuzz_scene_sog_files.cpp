// libFuzzer target: the SOG decoder behind the ZIP layer (meta.json v1/v2 and the WebP images),
// so mutations are not stopped by ZIP checksums. The input is a list of files, each
// [1 byte name length][name][4 bytes little-endian size][bytes]; `meta.json` must be one.
// The seeds are the files of fuzz/corpus/fuzz_scene_sog/tabletop24.sog in this layout, with
// its meta.json as written (v2) and rewritten as v1 (docs/fuzzing.md).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>

#include "scene/sog_files.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::map<std::string, std::string> files;
  size_t at = 0;
  while (at < size) {
    const size_t name_bytes = data[at++];
    if (size - at < name_bytes + 4) break;
    std::string name(reinterpret_cast<const char*>(data + at), name_bytes);
    at += name_bytes;
    uint32_t bytes;
    std::memcpy(&bytes, data + at, 4);
    at += 4;
    const size_t take = std::min<size_t>(bytes, size - at);
    files[name] = std::string(reinterpret_cast<const char*>(data + at), take);
    at += take;
  }
  const auto meta = files.find("meta.json");
  if (meta == files.end()) return 0;
  const lfd::scene::SogFileSource source = [&](const std::string& file) {
    const auto it = files.find(file);
    if (it == files.end()) lfd::throw_input_error("fuzz: no file '{}'", file);
    return it->second;
  };
  try {
    lfd::scene::read_sog_files(source, meta->second, "fuzz/meta.json");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
