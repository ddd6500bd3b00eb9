#include "util/image.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <stb_image.h>
#include <stb_image_write.h>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd {

Image8 read_image(const std::filesystem::path& path, int channels) {
  if (!std::filesystem::exists(path)) throw_input_error("{}: file not found", path.string());
  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.string().c_str(), &w, &h, &n, channels), stbi_image_free);
  if (!data) {
    throw_input_error("{}: not a readable image ({})", path.string(), stbi_failure_reason());
  }
  Image8 image(w, h, channels);
  std::copy(data.get(), data.get() + image.pixels.size(), image.pixels.begin());
  return image;
}

void write_png(const std::filesystem::path& path, const Image8& image) {
  if (image.width <= 0 || image.height <= 0)
    throw std::runtime_error(path.string() + ": refusing to write an empty image");
  write_file_atomic(path, [&](const std::filesystem::path& tmp) {
    const int ok = stbi_write_png(tmp.string().c_str(), image.width, image.height,
                                  image.channels, image.pixels.data(),
                                  image.width * image.channels);
    if (!ok) throw std::runtime_error(path.string() + ": cannot write PNG");
  });
}

ImageF to_float(const Image8& image) {
  ImageF out(image.width, image.height, image.channels);
  for (size_t i = 0; i < image.pixels.size(); ++i) out.pixels[i] = image.pixels[i] / 255.0f;
  return out;
}

Image8 to_uint8(const ImageF& image) {
  Image8 out(image.width, image.height, image.channels);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const float v = std::clamp(image.pixels[i], 0.0f, 1.0f);
    out.pixels[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
  }
  return out;
}

}  // namespace lfd
