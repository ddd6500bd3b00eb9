// The PNG writer and reader (util/png_codec.hpp behind util/image.hpp): what is written reads
// back exactly, every kind of PNG reads as stb_image reads it (the reader it replaced), and bad
// paths and files fail with an InputError naming the file, leaving nothing behind.
#include <png.h>
#include <stb_image.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/test_data.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

ImageF random_image(int w, int h, int c, unsigned seed) {
  ImageF img(w, h, c);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.1f, 1.1f);  // also values to clamp
  for (float& v : img.pixels) v = u(rng);
  return img;
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
  std::sort(out.begin(), out.end());
  return out;
}

// A PNG of any colour type, bit depth and interlacing with random samples, written with
// libpng's own API (not the code under test).
struct PngSpec {
  int width = 13, height = 7;
  int color_type = PNG_COLOR_TYPE_RGB;
  int bit_depth = 8;
  bool interlaced = false;
  bool transparent = false;  // a tRNS chunk (palette alpha, or a transparent gray/RGB colour)
};

int samples_per_pixel(int color_type) {
  switch (color_type) {
    case PNG_COLOR_TYPE_GRAY: return 1;
    case PNG_COLOR_TYPE_GRAY_ALPHA: return 2;
    case PNG_COLOR_TYPE_RGB: return 3;
    case PNG_COLOR_TYPE_RGB_ALPHA: return 4;
    default: return 1;  // palette index
  }
}

bool write_reference_png(const fs::path& path, const PngSpec& spec) {
  const int n = samples_per_pixel(spec.color_type);
  const int max = (1 << spec.bit_depth) - 1;
  std::mt19937 rng(7);
  std::vector<std::vector<png_byte>> rows(size_t(spec.height));
  for (auto& row : rows) {
    // Packed rows: libpng takes sub-byte samples packed, 16-bit samples big-endian.
    const size_t bits = size_t(spec.width) * n * spec.bit_depth;
    row.assign((bits + 7) / 8, 0);
    for (int i = 0; i < spec.width * n; ++i) {
      const unsigned v = rng() % unsigned(max + 1);
      if (spec.bit_depth == 16) {
        row[2 * size_t(i)] = png_byte(v >> 8);
        row[2 * size_t(i) + 1] = png_byte(v & 0xff);
      } else if (spec.bit_depth == 8) {
        row[size_t(i)] = png_byte(v);
      } else {
        const int per_byte = 8 / spec.bit_depth, shift = 8 - spec.bit_depth * (i % per_byte + 1);
        row[size_t(i / per_byte)] |= png_byte(v << shift);
      }
    }
  }
  std::vector<png_bytep> row_ptrs;
  for (auto& r : rows) row_ptrs.push_back(r.data());
  std::vector<png_color> palette;
  std::vector<png_byte> palette_alpha;
  for (int i = 0; i <= max && spec.color_type == PNG_COLOR_TYPE_PALETTE; ++i) {
    palette.push_back({png_byte(rng()), png_byte(rng()), png_byte(rng())});
    palette_alpha.push_back(png_byte(rng()));
  }
  png_color_16 transparent_colour{};
  transparent_colour.gray = transparent_colour.red = png_uint_16(max / 3);
  transparent_colour.green = transparent_colour.blue = png_uint_16(max / 3);

  std::FILE* f = std::fopen(path.string().c_str(), "wb");
  if (!f) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  volatile bool ok = false;
  if (!setjmp(png_jmpbuf(png))) {
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(spec.width), png_uint_32(spec.height), spec.bit_depth,
                 spec.color_type, spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!palette.empty()) png_set_PLTE(png, info, palette.data(), int(palette.size()));
    if (spec.transparent && !palette.empty())
      png_set_tRNS(png, info, palette_alpha.data(), int(palette_alpha.size()), nullptr);
    else if (spec.transparent)
      png_set_tRNS(png, info, nullptr, 0, &transparent_colour);
    png_write_info(png, info);
    png_write_image(png, row_ptrs.data());
    png_write_end(png, nullptr);
    ok = true;
  }
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
  return ok;
}

TEST(PngWriter, WritesAQuantisedImageThatReadsBackExactly) {
  const auto dir = test::temp_dir("png_writer_round_trip");
  for (int channels : {1, 3, 4}) {
    const Image8 quantised = to_uint8(random_image(67, 41, channels, unsigned(channels)));
    const fs::path path = dir / fmt::format("c{}.png", channels);
    write_png(path, quantised);
    const Image8 back = read_image(path, channels);
    EXPECT_EQ(back.width, 67);
    EXPECT_EQ(back.height, 41);
    EXPECT_EQ(back.channels, channels);
    EXPECT_EQ(back.pixels, quantised.pixels) << channels << " channels";
  }
}

TEST(PngWriter, WritesWhatStbImageReads) {
  const auto dir = test::temp_dir("png_writer_stb");
  const Image8 quantised = to_uint8(random_image(31, 17, 3, 5));
  write_png(dir / "q.png", quantised);
  int w = 0, h = 0, n = 0;
  stbi_uc* data = stbi_load((dir / "q.png").string().c_str(), &w, &h, &n, 3);
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(std::vector<uint8_t>(data, data + size_t(w) * h * 3), quantised.pixels);
  stbi_image_free(data);
}

TEST(PngWriter, ABadPathIsAnInputErrorNamingTheFileAndWritesNothing) {
  const auto dir = test::temp_dir("png_writer_bad_path");
  const Image8 image(4, 4, 3, 128);
  std::ofstream(dir / "plain.txt") << "a file, not a folder";
  fs::create_directory(dir / "folder.png");
  const auto before = files_in(dir);
  for (const fs::path& bad : {dir / "plain.txt" / "quilt.png", dir / "folder.png"}) {
    try {
      write_png(bad, image);
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(files_in(dir), before);
  EXPECT_TRUE(fs::is_empty(dir / "folder.png"));
}

TEST(PngWriter, ReplacesAnExistingFileWhole) {
  const auto dir = test::temp_dir("png_writer_replace");
  write_png(dir / "a.png", Image8(50, 30, 3, 200));
  const Image8 second = to_uint8(random_image(5, 3, 3, 9));
  write_png(dir / "a.png", second);
  EXPECT_EQ(read_image(dir / "a.png", 3).pixels, second.pixels);
  EXPECT_EQ(files_in(dir), std::vector<fs::path>{"a.png"});
}

// Every colour type and bit depth, tRNS and Adam7 interlacing, read as 1, 3 and 4 channels:
// the same values as stb_image, which lfd used before (so no caller sees a change).
TEST(PngReader, ReadsEveryKindOfPngAsStbImage) {
  const auto dir = test::temp_dir("png_reader_kinds");
  std::vector<std::pair<std::string, PngSpec>> kinds;
  const auto add = [&](std::string name, int type, int depth, bool trns = false, bool adam7 = false) {
    PngSpec s;
    s.color_type = type;
    s.bit_depth = depth;
    s.transparent = trns;
    s.interlaced = adam7;
    kinds.emplace_back(std::move(name), s);
  };
  add("gray1", PNG_COLOR_TYPE_GRAY, 1);
  add("gray4", PNG_COLOR_TYPE_GRAY, 4);
  add("gray8", PNG_COLOR_TYPE_GRAY, 8);
  add("gray8_trns", PNG_COLOR_TYPE_GRAY, 8, true);
  add("gray16", PNG_COLOR_TYPE_GRAY, 16);
  add("gray_alpha8", PNG_COLOR_TYPE_GRAY_ALPHA, 8);
  add("gray_alpha16", PNG_COLOR_TYPE_GRAY_ALPHA, 16);
  add("rgb8", PNG_COLOR_TYPE_RGB, 8);
  add("rgb8_trns", PNG_COLOR_TYPE_RGB, 8, true);
  add("rgb8_adam7", PNG_COLOR_TYPE_RGB, 8, false, true);
  add("rgb16", PNG_COLOR_TYPE_RGB, 16);
  add("rgba8", PNG_COLOR_TYPE_RGB_ALPHA, 8);
  add("rgba16_adam7", PNG_COLOR_TYPE_RGB_ALPHA, 16, false, true);
  add("palette2", PNG_COLOR_TYPE_PALETTE, 2);
  add("palette8", PNG_COLOR_TYPE_PALETTE, 8);
  add("palette8_trns", PNG_COLOR_TYPE_PALETTE, 8, true);
  for (const auto& [name, spec] : kinds) {
    const fs::path path = dir / (name + ".png");
    ASSERT_TRUE(write_reference_png(path, spec)) << name;
    for (int channels : {1, 3, 4}) {
      int w = 0, h = 0, n = 0;
      stbi_uc* data = stbi_load(path.string().c_str(), &w, &h, &n, channels);
      ASSERT_NE(data, nullptr) << name;
      const std::vector<uint8_t> expected(data, data + size_t(w) * h * channels);
      stbi_image_free(data);
      const Image8 image = read_image(path, channels);
      EXPECT_EQ(image.width, w);
      EXPECT_EQ(image.height, h);
      EXPECT_EQ(image.pixels, expected) << name << " read as " << channels << " channels";
    }
  }
}

TEST(PngReader, ATruncatedPngIsAnInputErrorNamingTheFile) {
  const auto dir = test::temp_dir("png_reader_truncated");
  write_png(dir / "whole.png", to_uint8(random_image(64, 64, 3, 3)));
  std::ifstream in(dir / "whole.png", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::ofstream(dir / "half.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  try {
    read_image(dir / "half.png");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("half.png"), std::string::npos) << e.what();
  }
}

// A header announcing 40000 x 40000 RGBA (6.4 GB) is refused before anything is allocated.
TEST(PngReader, AnAbsurdSizeIsRefusedNamingTheFile) {
  const auto dir = test::temp_dir("png_reader_huge");
  // The header and the first row (the reader needs an IDAT to get past the header).
  std::FILE* f = std::fopen((dir / "huge.png").string().c_str(), "wb");
  ASSERT_NE(f, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (!setjmp(png_jmpbuf(png))) {
    png_init_io(png, f);
    png_set_IHDR(png, info, 40000, 40000, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<png_byte> row(40000 * 4);
    std::mt19937 rng(1);
    for (auto& b : row) b = png_byte(rng());  // incompressible: libpng emits an IDAT at once
    png_write_row(png, row.data());
  }
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
  try {
    read_image(dir / "huge.png", 4);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lfd
