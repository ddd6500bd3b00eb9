// libpng reports errors by longjmp to the frame that called setjmp. Each function that calls
// setjmp below holds only trivially destructible objects and calls no C++ code that could
// throw, so the jump skips no destructor; the callers own every resource (RAII) and turn the
// returned failure into an exception.
#include "util/png_codec.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "util/error.hpp"

namespace lfd::png {
namespace {

// stb_image's limit on either side; libpng's own default is a million.
constexpr uint32_t kMaxSide = 1u << 24;
// Decoded images beyond this are refused before any allocation (a 2^31-byte image is a
// 26000 x 26000 RGB panel); stb_image refuses them too.
constexpr uint64_t kMaxDecodedBytes = uint64_t(1) << 31;

// zlib level 1 and the Up filter: the fastest setting that still compresses rendered quilts
// below stb_image_write's default output (docs/performance.md).
constexpr int kZlibLevel = 1;
constexpr int kRowFilter = PNG_FILTER_UP;

struct ErrorMessage {
  char text[200] = "";
};

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<ErrorMessage*>(png_get_error_ptr(png));
  std::snprintf(error->text, sizeof error->text, "%s", message);
  png_longjmp(png, 1);
}

// Warnings (a bad CRC on an ancillary chunk, an unknown chunk) do not stop a read or a write.
void on_warning(png_structp, png_const_charp) {}

struct ReadStruct {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~ReadStruct() { png_destroy_read_struct(&png, &info, nullptr); }
};

struct WriteStruct {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~WriteStruct() { png_destroy_write_struct(&png, &info); }
};

struct DecodedLayout {
  uint32_t width = 0, height = 0;
  int channels = 0;        // 1..4 after the transforms
  int bytes_per_sample = 0;  // 1, or 2 for 16-bit files (host byte order)
};

// Reads the header and sets the transforms that make every PNG gray, gray + alpha, RGB or RGBA
// of 8 or 16 bits. 16-bit samples stay 16-bit because stb_image converts channels before it
// drops the low byte (its luma of 16-bit colour differs from the luma of the high bytes).
// setjmp frame (see the top of the file).
bool read_layout(png_structp png, png_infop info, std::FILE* file, DecodedLayout* layout) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_sig_bytes(png, 8);
  png_set_user_limits(png, kMaxSide, kMaxSide);
  png_read_info(png, info);
  png_set_expand(png);  // palette -> RGB, gray below 8 bits -> 8 bits, tRNS -> alpha
  if (png_get_bit_depth(png, info) == 16) {
    const uint16_t one = 1;
    if (*reinterpret_cast<const uint8_t*>(&one) == 1) png_set_swap(png);  // big-endian on disk
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  layout->width = png_get_image_width(png, info);
  layout->height = png_get_image_height(png, info);
  layout->channels = png_get_channels(png, info);
  layout->bytes_per_sample = png_get_bit_depth(png, info) == 16 ? 2 : 1;
  return true;
}

// setjmp frame. The image end (IEND and what follows the pixels) is not read: a file whose
// pixels are complete is readable, as with stb_image.
bool read_rows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  return true;
}

// setjmp frame.
bool write_image(png_structp png, png_infop info, std::FILE* file, const Image8& image,
                 int color_type) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_compression_level(png, kZlibLevel);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, kRowFilter);
  png_set_IHDR(png, info, uint32_t(image.width), uint32_t(image.height), 8, color_type,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) png_write_row(png, image.row(y));
  png_write_end(png, nullptr);
  return true;
}

// One pixel from `n` channels (1 gray, 2 gray + alpha, 3 RGB, 4 RGBA) of 8 or 16 bits to `m`
// 8-bit channels (1, 3 or 4), as stb_image: stbi__convert_format(16) with its integer luma
// (stbi__compute_y), then the high byte of 16-bit samples (stbi__convert_16_to_8).
template <typename Sample>
inline void convert_pixel(const Sample* in, int n, uint8_t* out, int m) {
  constexpr int kDrop = sizeof(Sample) == 2 ? 8 : 0;
  constexpr unsigned kOpaque = sizeof(Sample) == 2 ? 0xffff : 0xff;
  const bool colour = n >= 3;
  const bool alpha = n == 2 || n == 4;
  if (m == 1) {
    const unsigned y = colour ? (in[0] * 77u + in[1] * 150u + in[2] * 29u) >> 8 : in[0];
    out[0] = uint8_t((y & kOpaque) >> kDrop);
    return;
  }
  for (int c = 0; c < 3; ++c) out[c] = uint8_t((colour ? in[c] : in[0]) >> kDrop);
  if (m == 4) out[3] = uint8_t((alpha ? unsigned(in[n - 1]) : kOpaque) >> kDrop);
}

template <typename Sample>
Image8 convert(const std::vector<Sample>& samples, const DecodedLayout& layout, int channels) {
  Image8 out(int(layout.width), int(layout.height), channels);
  const size_t pixels = size_t(layout.width) * layout.height;
  for (size_t i = 0; i < pixels; ++i)
    convert_pixel(&samples[i * size_t(layout.channels)], layout.channels,
                  &out.pixels[i * size_t(channels)], channels);
  return out;
}

}  // namespace

bool has_png_signature(std::FILE* file) {
  png_byte signature[8];
  return std::fread(signature, 1, 8, file) == 8 && png_sig_cmp(signature, 0, 8) == 0;
}

Image8 decode(std::FILE* file, const std::string& name, int channels) {
  ErrorMessage error;
  ReadStruct s;
  s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_error, on_warning);
  if (s.png) s.info = png_create_info_struct(s.png);
  if (!s.info) throw std::runtime_error(name + ": cannot initialise libpng");
  DecodedLayout layout;
  if (!read_layout(s.png, s.info, file, &layout))
    throw_input_error("{}: not a readable PNG ({})", name, error.text);
  const size_t row_samples = size_t(layout.width) * size_t(layout.channels);
  const uint64_t bytes = uint64_t(row_samples) * layout.height * uint64_t(layout.bytes_per_sample);
  if (bytes > kMaxDecodedBytes)
    throw_input_error("{}: PNG of {}x{} pixels is too large (more than {} bytes decoded)", name,
                      layout.width, layout.height, kMaxDecodedBytes);

  std::vector<png_bytep> rows(layout.height);
  if (layout.bytes_per_sample == 2) {
    std::vector<uint16_t> samples(row_samples * layout.height);
    for (uint32_t y = 0; y < layout.height; ++y)
      rows[y] = reinterpret_cast<png_bytep>(&samples[y * row_samples]);
    if (!read_rows(s.png, rows.data()))
      throw_input_error("{}: not a readable PNG ({})", name, error.text);
    return convert(samples, layout, channels);
  }
  // 8-bit files in the requested channels (every file lfd writes, read back) go straight into
  // the image.
  Image8 decoded(int(layout.width), int(layout.height), layout.channels);
  for (uint32_t y = 0; y < layout.height; ++y) rows[y] = decoded.row(int(y));
  if (!read_rows(s.png, rows.data()))
    throw_input_error("{}: not a readable PNG ({})", name, error.text);
  return layout.channels == channels ? decoded : convert(decoded.pixels, layout, channels);
}

void encode(std::FILE* file, const std::string& name, const Image8& image) {
  static constexpr int kColorType[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                       PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGBA};
  if (image.channels < 1 || image.channels > 4)
    throw std::invalid_argument(name + ": PNG images have 1 to 4 channels");
  ErrorMessage error;
  WriteStruct s;
  s.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_error, on_warning);
  if (s.png) s.info = png_create_info_struct(s.png);
  if (!s.info) throw std::runtime_error(name + ": cannot initialise libpng");
  if (!write_image(s.png, s.info, file, image, kColorType[image.channels - 1]))
    throw std::runtime_error(name + ": cannot write PNG (" + error.text + ")");
}

std::string encode_to_bytes(const std::string& name, const Image8& image) {
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* memory = open_memstream(&data, &size);
  if (!memory) throw std::runtime_error(name + ": no memory stream for the PNG");
  try {
    encode(memory, name, image);
  } catch (...) {
    std::fclose(memory);
    std::free(data);
    throw;
  }
  std::fclose(memory);  // sets data and size
  std::string bytes(data, size);
  std::free(data);
  return bytes;
}

}  // namespace lfd::png
