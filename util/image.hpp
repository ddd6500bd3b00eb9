#pragma once
// Images in memory: row 0 = top (as on disk), interleaved channels.
// Image8 holds 8-bit sRGB values as stored in PNG files; ImageF holds floats in [0, 1].
#include <cstdint>
#include <filesystem>
#include <vector>

namespace lfd {

template <typename T>
struct ImageT {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<T> pixels;

  ImageT() = default;
  ImageT(int w, int h, int c, T fill = T{})
      : width(w), height(h), channels(c), pixels(size_t(w) * size_t(h) * size_t(c), fill) {}

  bool empty() const { return pixels.empty(); }
  T& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  const T& at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
  T* row(int y) { return pixels.data() + size_t(y) * width * channels; }
  const T* row(int y) const { return pixels.data() + size_t(y) * width * channels; }
};

using Image8 = ImageT<uint8_t>;
using ImageF = ImageT<float>;

// Reads a PNG (or any format stb_image reads) as `channels` channels (1, 3 or 4).
// Throws InputError naming the file when it is missing or not a readable image.
Image8 read_image(const std::filesystem::path& path, int channels = 3);

// Writes a PNG atomically (temp file + rename). Throws on I/O failure.
void write_png(const std::filesystem::path& path, const Image8& image);

// Conversions between 8-bit values and floats in [0, 1] (no colour-space change).
ImageF to_float(const Image8& image);
Image8 to_uint8(const ImageF& image);

}  // namespace lfd
