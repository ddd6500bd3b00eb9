#pragma once
// Quilt images (PNG, JPEG, WebP) from a file or from bytes in memory (docs/play.md): decoded to
// 8-bit RGB with the loaders lfd already uses (stb_image for PNG/JPEG in memory, libpng through
// util::read_image for PNG files) and libwebp for WebP. The dimensions are read from the header
// and bounded BEFORE any pixel is decoded, so a hostile file cannot ask for gigabytes.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "interlace/quilt_file.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::media {

// The largest picture accepted: 16384 px per side and 2^27 pixels (384 MiB as RGB). The
// largest Looking Glass quilts are 8192 x 8192 (2^26).
inline constexpr int kMaxImageSide = 16384;
inline constexpr int64_t kMaxImagePixels = int64_t(1) << 27;
// Files larger than this are not read into memory (a 2^27-pixel PNG compresses far below it).
inline constexpr int64_t kMaxImageFileBytes = int64_t(1) << 30;

enum class ImageFormat { kUnknown, kPng, kJpeg, kWebp };
// From the first bytes (signature), not the name.
ImageFormat sniff_image_format(std::span<const uint8_t> bytes);

// The picture's width and height from its header, checked against the bounds above, without
// decoding a pixel (what a caller budgets before decode_image). InputError as decode_image.
struct ImageSize {
  int width = 0, height = 0;
};
ImageSize image_size(std::span<const uint8_t> bytes, const std::string& name);

// Decodes bytes to RGB (3 channels, rows top-down). InputError "NAME: ..." for an unknown or
// corrupt format, a truncated file, or a picture over the bounds above.
Image8 decode_image(std::span<const uint8_t> bytes, const std::string& name);

// The whole file (bounded by kMaxImageFileBytes); InputError naming it when it cannot be read.
std::vector<uint8_t> read_file_bytes(const std::filesystem::path& path, int64_t max_bytes = kMaxImageFileBytes);

struct QuiltImage {
  Image8 pixels;               // RGB, rows top-down
  render::QuiltLayout layout;  // from the name (media/quilt_name.hpp) or the overrides
};

// A quilt from bytes called `name` (its `_qsCxRaA` gives the tiling unless overridden).
QuiltImage decode_quilt_image(std::span<const uint8_t> bytes, const std::string& name,
                              const interlace::QuiltOverrides& overrides, double display_aspect);
// A quilt image file.
QuiltImage read_quilt_image(const std::filesystem::path& path, const interlace::QuiltOverrides& overrides,
                            double display_aspect);

}  // namespace lfd::media

namespace lfd::media {
// Whether a file is a picture (PNG, JPEG or WebP by its first bytes) rather than a video.
// InputError naming it when it cannot be opened.
bool is_image_file(const std::filesystem::path& path);
}  // namespace lfd::media
