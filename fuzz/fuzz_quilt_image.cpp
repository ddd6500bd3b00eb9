// libFuzzer target: quilt pictures from bytes (media::decode_image: PNG and JPEG through
// stb_image, WebP through libwebp). Any input either decodes to an RGB picture within the
// bounds or throws lfd::InputError; the bounds are checked before pixel memory is taken.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "media/quilt_image.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace lfd::media;
  try {
    const lfd::Image8 image = decode_image(std::span<const uint8_t>(data, size), "fuzz.png");
    if (image.channels != 3 || image.width < 1 || image.height < 1 || image.width > kMaxImageSide ||
        image.height > kMaxImageSide || int64_t(image.width) * image.height > kMaxImagePixels)
      std::abort();
  } catch (const lfd::InputError&) {
  }
  return 0;
}
