// Decoding a quilt from memory (docs/serve.md).
#include "serve/quilt_bytes.hpp"

#include <cstdio>
#include <memory>

#include <stb_image.h>

#include "util/error.hpp"
#include "util/png_codec.hpp"

namespace lfd::serve {

Image8 decode_quilt_bytes(std::span<const std::uint8_t> bytes, const std::string& name, int max_side_px) {
  if (bytes.empty()) throw_input_error("{}: no image bytes", name);
  if (bytes.size() > static_cast<std::size_t>(INT32_MAX)) throw_input_error("{}: too large", name);
  int w = 0, h = 0, n = 0;
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());
  if (!stbi_info_from_memory(data, size, &w, &h, &n))
    throw_input_error("{}: not a readable image ({})", name, stbi_failure_reason());
  if (w <= 0 || h <= 0 || w > max_side_px || h > max_side_px)
    throw_input_error("{}: {} x {} pixels is over the limit of {} a side", name, w, h, max_side_px);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(
      fmemopen(const_cast<std::uint8_t*>(bytes.data()), bytes.size(), "rb"), &std::fclose);
  if (file && png::has_png_signature(file.get())) return png::decode(file.get(), name, 3);
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_memory(data, size, &w, &h, &n, 3),
                                                   stbi_image_free);
  if (!pixels) throw_input_error("{}: not a readable image ({})", name, stbi_failure_reason());
  Image8 image(w, h, 3);
  std::copy(pixels.get(), pixels.get() + image.pixels.size(), image.pixels.begin());
  return image;
}

}  // namespace lfd::serve
