#include "util/image.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <stb_image.h>

#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "util/png_codec.hpp"

namespace lfd {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// Any format but PNG (JPEG, BMP, ...): stb_image.
Image8 read_with_stb(std::FILE* file, const std::string& name, int channels) {
  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load_from_file(file, &w, &h, &n, channels),
                                                 stbi_image_free);
  if (!data) throw_input_error("{}: not a readable image ({})", name, stbi_failure_reason());
  Image8 image(w, h, channels);
  std::copy(data.get(), data.get() + image.pixels.size(), image.pixels.begin());
  return image;
}

}  // namespace

Image8 read_image(const std::filesystem::path& path, int channels) {
  const std::string name = path.string();
  if (channels != 1 && channels != 3 && channels != 4)
    throw std::invalid_argument(name + ": images are read as 1, 3 or 4 channels");
  if (!std::filesystem::exists(path)) throw_input_error("{}: file not found", name);
  const File file(std::fopen(name.c_str(), "rb"));
  if (!file) throw_input_error("{}: cannot open ({})", name, std::strerror(errno));
  if (png::has_png_signature(file.get())) return png::decode(file.get(), name, channels);
  std::rewind(file.get());
  return read_with_stb(file.get(), name, channels);
}

void write_png(const std::filesystem::path& path, const Image8& image) {
  const std::string name = path.string();
  if (image.width <= 0 || image.height <= 0)
    throw std::runtime_error(name + ": refusing to write an empty image");
  try {
    write_file_atomic(path, [&](const std::filesystem::path& tmp) {
      const File file(std::fopen(tmp.string().c_str(), "wb"));
      if (!file) throw_input_error("{}: cannot create ({})", name, std::strerror(errno));
      // Large stdio buffer: a quilt is tens of MB, written in row-sized pieces.
      std::setvbuf(file.get(), nullptr, _IOFBF, size_t(1) << 20);
      png::encode(file.get(), name, image);
      if (std::fflush(file.get()) != 0 || std::ferror(file.get()))
        throw std::runtime_error(name + ": cannot write PNG (" + std::strerror(errno) + ")");
    });
  } catch (const std::filesystem::filesystem_error& e) {
    // The folder cannot be made, or the path is a folder: the rename or mkdir refused.
    throw_input_error("{}: cannot write ({})", name, e.code().message());
  }
}

// A quilt is 35 M values: both conversions run in parallel.
ImageF to_float(const Image8& image) {
  ImageF out(image.width, image.height, image.channels);
  const long n = long(image.pixels.size());
  const uint8_t* in = image.pixels.data();
  float* o = out.pixels.data();
#pragma omp parallel for schedule(static) if (n > (1 << 20))
  for (long i = 0; i < n; ++i) o[i] = in[i] / 255.0f;
  return out;
}

Image8 to_uint8(const ImageF& image) {
  Image8 out(image.width, image.height, image.channels);
  const long n = long(image.pixels.size());
  const float* in = image.pixels.data();
  uint8_t* o = out.pixels.data();
#pragma omp parallel for schedule(static) if (n > (1 << 20))
  for (long i = 0; i < n; ++i) {
    // lround(v * 255) of the clamped value (NaN -> 0), without the libm call: v * 255 is a
    // float, so adding 0.5 in double is exact and truncation rounds half up as lround.
    const float v = (in[i] > 0.0f ? std::min(in[i], 1.0f) : 0.0f) * 255.0f;
    o[i] = uint8_t(double(v) + 0.5);
  }
  return out;
}

}  // namespace lfd
