// libFuzzer target: the SPZ v1-v3 payload behind the gzip layer. Mutating gzip bytes rarely
// yields valid deflate data, so this target gzips its input first and lets the fuzzer explore
// the header, size checks and attribute decoding directly.
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "render/scene_parsers.hpp"
#include "util/error.hpp"

namespace {

std::string gzip(std::string_view data) {
  z_stream z{};
  deflateInit2(&z, 1, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&z, uLong(data.size())) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = uInt(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string compressed = gzip({reinterpret_cast<const char*>(data), size});
  try {
    lfd::render::read_spz(compressed, "fuzz.spz");
  } catch (const lfd::InputError&) {
  }
  return 0;
}
