#pragma once
// Images in memory: row 0 = top (as on disk), interleaved channels.
// Image8 holds 8-bit sRGB values as stored in PNG files; ImageF holds floats in [0, 1].
#include <cstdint>
#include <filesystem>
#include <vector>

#include "util/huge_pages.hpp"

namespace lfd {

template <typename T>
struct ImageT {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<T> pixels;

  ImageT() = default;
  // Quilts and panels are large: their pixels go on huge pages (util/huge_pages.hpp).
  ImageT(int w, int h, int c, T fill = T{}) : width(w), height(h), channels(c) {
    assign_large(pixels, size_t(w) * size_t(h) * size_t(c), fill);
  }

  bool empty() const { return pixels.empty(); }
  T& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  const T& at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
  T* row(int y) { return pixels.data() + size_t(y) * width * channels; }
  const T* row(int y) const { return pixels.data() + size_t(y) * width * channels; }
};

using Image8 = ImageT<uint8_t>;
using ImageF = ImageT<float>;

// Reads a PNG (libpng) or any other format stb_image reads, as `channels` channels (1, 3 or 4),
// with stb_image's conversions (util/png_codec.hpp). Throws InputError naming the file when it
// is missing or not a readable image.
Image8 read_image(const std::filesystem::path& path, int channels = 3);

// Writes an 8-bit PNG (1 to 4 channels) atomically (temp file + rename; util/atomic_file.hpp),
// fast (util/png_codec.hpp). Throws InputError naming the file when it cannot be created (its
// folder cannot be made, the path is a folder), std::runtime_error on a write error; neither
// leaves a file behind.
void write_png(const std::filesystem::path& path, const Image8& image);

// Conversions between 8-bit values and floats in [0, 1] (no colour-space change).
ImageF to_float(const Image8& image);
Image8 to_uint8(const ImageF& image);

}  // namespace lfd
