// Quilt images from bytes: PNG, JPEG and WebP decode to the pixels that were encoded; a header
// claiming a huge picture, a truncated file and an unknown format are one-line errors naming
// the file, before any pixel memory is taken.
#include <filesystem>

#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <webp/encode.h>

#include "media/quilt_image.hpp"
#include "media/synthetic_quilt.hpp"
#include "render/image_metrics.hpp"
#include "tests/support/quilt_layouts.hpp"
#include "util/error.hpp"

namespace lfd::media {
namespace {

namespace fs = std::filesystem;

render::QuiltLayout small_layout() { return test::quilt_layout(4, 2, 128, 64); }

std::vector<uint8_t> png_bytes(const Image8& image) {
  const fs::path path = fs::temp_directory_path() / "lfd_media_quilt_image_test.png";
  write_png(path, image);
  return read_file_bytes(path);
}

std::string error_of(const std::vector<uint8_t>& bytes, const std::string& name) {
  try {
    decode_image(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(QuiltImage, PngFromBytesIsExact) {
  const Image8 source = synthetic_quilt(small_layout());
  const Image8 decoded = decode_image(png_bytes(source), "q.png");
  ASSERT_EQ(decoded.width, source.width);
  ASSERT_EQ(decoded.height, source.height);
  EXPECT_EQ(decoded.pixels, source.pixels);
}

TEST(QuiltImage, WebpLosslessIsExact) {
  const Image8 source = synthetic_quilt(small_layout());
  uint8_t* out = nullptr;
  const size_t size = WebPEncodeLosslessRGB(source.pixels.data(), source.width, source.height, source.width * 3, &out);
  ASSERT_GT(size, 0u);
  const std::vector<uint8_t> bytes(out, out + size);
  WebPFree(out);
  EXPECT_EQ(sniff_image_format(bytes), ImageFormat::kWebp);
  EXPECT_EQ(decode_image(bytes, "q.webp").pixels, source.pixels);
}

TEST(QuiltImage, JpegIsClose) {
  const Image8 source = synthetic_quilt(small_layout());
  std::vector<uint8_t> bytes;
  stbi_write_jpg_to_func(
      [](void* context, void* data, int size) {
        auto* b = static_cast<std::vector<uint8_t>*>(context);
        b->insert(b->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
      },
      &bytes, source.width, source.height, 3, source.pixels.data(), 95);
  EXPECT_EQ(sniff_image_format(bytes), ImageFormat::kJpeg);
  EXPECT_GE(render::psnr(to_float(decode_image(bytes, "q.jpg")), to_float(source)), 30.0);
}

TEST(QuiltImage, QuiltFromBytesTakesTheTilingFromTheName) {
  const Image8 source = synthetic_quilt(small_layout());
  const QuiltImage q = decode_quilt_image(png_bytes(source), "scene_qs4x2a1.png", {}, 0.75);
  EXPECT_EQ(q.layout.cols, 4);
  EXPECT_EQ(q.layout.rows, 2);
  EXPECT_EQ(q.layout.width, 128);
  EXPECT_THROW(decode_quilt_image(png_bytes(source), "scene_qs40x2a1.png", {}, 0.75), InputError);
}

// A valid PNG signature and IHDR claiming 100000 x 100000: refused from the header.
TEST(QuiltImage, HugeHeaderIsRefusedBeforeDecoding) {
  std::vector<uint8_t> bytes = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
  for (const uint32_t side : {100000u, 100000u})
    for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(uint8_t(side >> shift));
  for (const uint8_t b : {8, 2, 0, 0, 0, 0, 0, 0, 0}) bytes.push_back(b);  // depth, RGB, methods, CRC
  const std::string error = error_of(bytes, "huge.png");
  EXPECT_NE(error.find("huge.png"), std::string::npos) << error;
  EXPECT_NE(error.find("100000x100000"), std::string::npos) << error;
}

TEST(QuiltImage, TruncatedAndUnknownAreErrorsNamingTheFile) {
  std::vector<uint8_t> bytes = png_bytes(synthetic_quilt(small_layout()));
  bytes.resize(bytes.size() / 2);
  EXPECT_NE(error_of(bytes, "cut.png").find("cut.png"), std::string::npos);
  const std::vector<uint8_t> text = {'h', 'e', 'l', 'l', 'o'};
  EXPECT_NE(error_of(text, "text.png").find("not a PNG, JPEG or WebP"), std::string::npos);
  EXPECT_NE(error_of({}, "empty.png").find("empty.png"), std::string::npos);
}

}  // namespace
}  // namespace lfd::media
