#include "media/quilt_image.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <memory>

#include <stb_image.h>
#include <webp/decode.h>

#include "media/quilt_name.hpp"
#include "util/error.hpp"

namespace lfd::media {
namespace {

void check_size(const std::string& name, int width, int height) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide ||
      int64_t(width) * height > kMaxImagePixels)
    throw_input_error("{}: a {}x{} image is outside the bounds (at most {} px a side, {} Mpx)", name, width,
                      height, kMaxImageSide, kMaxImagePixels >> 20);
}

// A PNG's size from its IHDR (the first chunk), so a huge claim is refused with the bounds
// rather than stb's "too large" lost among its format probes.
void check_png_header(std::span<const uint8_t> b, const std::string& name) {
  if (b.size() < 24 || std::memcmp(b.data() + 12, "IHDR", 4) != 0) return;  // stb says what is wrong
  auto be32 = [&](size_t at) { return uint32_t(b[at]) << 24 | uint32_t(b[at + 1]) << 16 | uint32_t(b[at + 2]) << 8 | b[at + 3]; };
  const uint32_t w = be32(16), h = be32(20);
  if (w > uint32_t(kMaxImageSide) || h > uint32_t(kMaxImageSide)) check_size(name, int(std::min<uint32_t>(w, INT32_MAX)), int(std::min<uint32_t>(h, INT32_MAX)));
}

Image8 decode_with_stb(std::span<const uint8_t> bytes, const std::string& name) {
  if (bytes.size() > size_t(INT32_MAX)) throw_input_error("{}: file too large", name);
  if (sniff_image_format(bytes) == ImageFormat::kPng) check_png_header(bytes, name);
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(bytes.data(), int(bytes.size()), &w, &h, &n))
    throw_input_error("{}: not a readable image ({})", name, stbi_failure_reason());
  check_size(name, w, h);
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &n, 3), stbi_image_free);
  if (!data) throw_input_error("{}: not a readable image ({})", name, stbi_failure_reason());
  Image8 image(w, h, 3);
  std::copy_n(data.get(), image.pixels.size(), image.pixels.begin());
  return image;
}

Image8 decode_webp(std::span<const uint8_t> bytes, const std::string& name) {
  int w = 0, h = 0;
  if (!WebPGetInfo(bytes.data(), bytes.size(), &w, &h)) throw_input_error("{}: not a readable WebP image", name);
  check_size(name, w, h);
  Image8 image(w, h, 3);
  if (!WebPDecodeRGBInto(bytes.data(), bytes.size(), image.pixels.data(), image.pixels.size(), w * 3))
    throw_input_error("{}: corrupt or truncated WebP image", name);
  return image;
}

}  // namespace

ImageFormat sniff_image_format(std::span<const uint8_t> b) {
  auto starts = [&](size_t at, const char* magic) {
    const size_t n = std::strlen(magic);
    return b.size() >= at + n && std::memcmp(b.data() + at, magic, n) == 0;
  };
  if (starts(0, "\x89PNG\r\n\x1a\n")) return ImageFormat::kPng;
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return ImageFormat::kJpeg;
  if (starts(0, "RIFF") && starts(8, "WEBP")) return ImageFormat::kWebp;
  return ImageFormat::kUnknown;
}

ImageSize image_size(std::span<const uint8_t> bytes, const std::string& name) {
  ImageSize size;
  switch (sniff_image_format(bytes)) {
    case ImageFormat::kPng:
    case ImageFormat::kJpeg: {
      if (bytes.size() > size_t(INT32_MAX)) throw_input_error("{}: file too large", name);
      if (sniff_image_format(bytes) == ImageFormat::kPng) check_png_header(bytes, name);
      int n = 0;
      if (!stbi_info_from_memory(bytes.data(), int(bytes.size()), &size.width, &size.height, &n))
        throw_input_error("{}: not a readable image ({})", name, stbi_failure_reason());
      break;
    }
    case ImageFormat::kWebp:
      if (!WebPGetInfo(bytes.data(), bytes.size(), &size.width, &size.height))
        throw_input_error("{}: not a readable WebP image", name);
      break;
    case ImageFormat::kUnknown: throw_input_error("{}: not a PNG, JPEG or WebP image", name);
  }
  check_size(name, size.width, size.height);
  return size;
}

Image8 decode_image(std::span<const uint8_t> bytes, const std::string& name) {
  switch (sniff_image_format(bytes)) {
    case ImageFormat::kPng:
    case ImageFormat::kJpeg: return decode_with_stb(bytes, name);
    case ImageFormat::kWebp: return decode_webp(bytes, name);
    case ImageFormat::kUnknown: break;
  }
  throw_input_error("{}: not a PNG, JPEG or WebP image", name);
}

std::vector<uint8_t> read_file_bytes(const std::filesystem::path& path, int64_t max_bytes) {
  const std::string name = path.string();
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw_input_error("{}: cannot read ({})", name, ec.message());
  if (int64_t(size) > max_bytes) throw_input_error("{}: {} bytes is more than the {} accepted", name, size, max_bytes);
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes(size);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
    throw_input_error("{}: cannot read", name);
  return bytes;
}

QuiltImage decode_quilt_image(std::span<const uint8_t> bytes, const std::string& name,
                              const interlace::QuiltOverrides& overrides, double display_aspect) {
  QuiltImage q;
  q.pixels = decode_image(bytes, name);
  q.layout = quilt_layout_for(name, q.pixels.width, q.pixels.height, overrides, display_aspect);
  return q;
}

QuiltImage read_quilt_image(const std::filesystem::path& path, const interlace::QuiltOverrides& overrides,
                            double display_aspect) {
  return decode_quilt_image(read_file_bytes(path), path.string(), overrides, display_aspect);
}

}  // namespace lfd::media

namespace lfd::media {
bool is_image_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in || !std::filesystem::is_regular_file(path)) throw_input_error("{}: file not found", path.string());
  uint8_t head[16] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  return sniff_image_format(std::span<const uint8_t>(head, size_t(in.gcount()))) != ImageFormat::kUnknown;
}
}  // namespace lfd::media
