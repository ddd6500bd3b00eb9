// libFuzzer target: the `_qsCxRaA` quilt name (media::parse_quilt_name) and the tiling it gives a
// picture (media::quilt_layout_for). The first 4 bytes are the picture's size (two 16-bit
// numbers), the rest the file name. A parsed name must be within the bounds; the layout must
// either come out usable or throw lfd::InputError.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "media/quilt_name.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 4) return 0;
  const int width = data[0] | data[1] << 8, height = data[2] | data[3] << 8;
  const std::string name(reinterpret_cast<const char*>(data + 4), size - 4);
  using namespace lfd::media;
  if (const auto q = parse_quilt_name(name)) {
    if (q->cols < 1 || q->cols > kMaxQuiltTilesPerAxis || q->rows < 1 || q->rows > kMaxQuiltTilesPerAxis ||
        !(q->aspect >= kMinQuiltAspect && q->aspect <= kMaxQuiltAspect))
      std::abort();
  }
  try {
    const auto layout = quilt_layout_for(name, width, height, {}, 0.75);
    if (layout.tile_width() < kMinQuiltTilePx || layout.tile_height() < kMinQuiltTilePx ||
        layout.views > layout.cols * layout.rows)
      std::abort();
  } catch (const lfd::InputError&) {
  }
  return 0;
}
