// libFuzzer target: the SPZ v1-v3 payload behind the gzip layer. Mutating gzip bytes rarely
// yields valid deflate data, so this target gzips its input first and lets the fuzzer explore
// the header, size checks and attribute decoding directly.
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "tests/scene/gzip_for_tests.hpp"
#include "scene/scene_parsers.hpp"
#include "util/error.hpp"

namespace {

std::string gzip(std::string_view data) { return lfd::test::gzip(data, 1); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string compressed = gzip({reinterpret_cast<const char*>(data), size});
  try {
    lfd::scene::read_spz(compressed, "fuzz.spz");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
