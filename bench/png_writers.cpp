// lfd_bench_png: how fast stb_image_write, libpng and libspng write (and read) one image, to
// choose lfd's PNG library (docs/performance.md, "Writing PNG"). Median of --runs after one
// warm-up, min-max, and the file size, per library and setting; lfd's own setting
// (util/png_codec.hpp: libpng, zlib level 1, Up filter) is one of the libpng rows. Built when
// libspng is installed (libspng-dev); not part of lfd.
//   lfd_bench_png quilt_qs5x9a1.png [--runs 5]
#include <png.h>
#include <spng.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

const char* kOut = "lfd_bench_png.tmp.png";

void fail(const char* what) {
  std::fprintf(stderr, "lfd_bench_png: %s\n", what);
  std::exit(1);
}

long file_size(const char* path) {
  struct stat s {};
  return stat(path, &s) == 0 ? long(s.st_size) : -1;
}

void write_stb(const Image& im, int level) {
  stbi_write_png_compression_level = level;
  if (!stbi_write_png(kOut, im.width, im.height, 3, im.rgb.data(), im.width * 3)) fail("stb write");
}

// setjmp frame: only trivially destructible locals.
bool write_libpng_rows(png_structp png, png_infop info, std::FILE* f, const Image& im, int level,
                       int filters) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, f);
  png_set_compression_level(png, level);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
  png_set_IHDR(png, info, png_uint_32(im.width), png_uint_32(im.height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < im.height; ++y) png_write_row(png, im.rgb.data() + size_t(y) * im.width * 3);
  png_write_end(png, nullptr);
  return true;
}

void write_libpng(const Image& im, int level, int filters) {
  std::FILE* f = std::fopen(kOut, "wb");
  if (!f) fail("cannot create the output");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  const bool ok = write_libpng_rows(png, info, f, im, level, filters);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
  if (!ok) fail("libpng write");
}

void write_spng(const Image& im, int level, int filters) {
  std::FILE* f = std::fopen(kOut, "wb");
  if (!f) fail("cannot create the output");
  spng_ctx* ctx = spng_ctx_new(SPNG_CTX_ENCODER);
  spng_set_png_file(ctx, f);
  spng_set_option(ctx, SPNG_IMG_COMPRESSION_LEVEL, level);
  spng_set_option(ctx, SPNG_FILTER_CHOICE, filters);
  spng_ihdr ihdr{};
  ihdr.width = uint32_t(im.width);
  ihdr.height = uint32_t(im.height);
  ihdr.bit_depth = 8;
  ihdr.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
  spng_set_ihdr(ctx, &ihdr);
  const int e = spng_encode_image(ctx, im.rgb.data(), im.rgb.size(), SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE);
  spng_ctx_free(ctx);
  std::fclose(f);
  if (e) fail(spng_strerror(e));
}

void read_stb() {
  int w, h, n;
  stbi_uc* d = stbi_load(kOut, &w, &h, &n, 3);
  if (!d) fail("stb read");
  stbi_image_free(d);
}

void read_spng() {
  std::FILE* f = std::fopen(kOut, "rb");
  spng_ctx* ctx = spng_ctx_new(0);
  spng_set_png_file(ctx, f);
  size_t n = 0;
  spng_decoded_image_size(ctx, SPNG_FMT_RGB8, &n);
  std::vector<unsigned char> out(n);
  const int e = spng_decode_image(ctx, out.data(), n, SPNG_FMT_RGB8, 0);
  spng_ctx_free(ctx);
  std::fclose(f);
  if (e) fail(spng_strerror(e));
}

void read_libpng() {
  png_image im{};
  im.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&im, kOut)) fail("libpng read");
  im.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> out(PNG_IMAGE_SIZE(im));
  if (!png_image_finish_read(&im, nullptr, out.data(), 0, nullptr)) fail("libpng read");
}

void row(const std::string& name, int runs, const std::function<void()>& f) {
  f();  // warm-up
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  std::printf("| %s | %.3f | %.3f-%.3f | %.2f |\n", name.c_str(), t[t.size() / 2], t.front(),
              t.back(), double(file_size(kOut)) / 1e6);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0) {
    std::printf("Usage: lfd_bench_png IMAGE.png [--runs N]\n");
    return argc < 2 ? 2 : 0;
  }
  int runs = 5;
  if (argc == 4 && std::strcmp(argv[2], "--runs") == 0) runs = std::max(1, std::atoi(argv[3]));
  Image im;
  int n = 0;
  stbi_uc* d = stbi_load(argv[1], &im.width, &im.height, &n, 3);
  if (!d) fail("cannot read the image");
  im.rgb.assign(d, d + size_t(im.width) * im.height * 3);
  stbi_image_free(d);
  std::printf("%s: %dx%d RGB (%.1f MB raw); median of %d runs after a warm-up\n\n", argv[1],
              im.width, im.height, double(im.rgb.size()) / 1e6, runs);
  std::printf("| writer | median [s] | min-max [s] | file [MB] |\n|---|---:|---:|---:|\n");
  row("stb_image_write (lfd before; level 8, filter per row)", runs, [&] { write_stb(im, 8); });
  row("stb_image_write, level 1", runs, [&] { write_stb(im, 1); });
  struct Filter {
    const char* name;
    int libpng, spng;
  };
  const Filter filters[] = {{"none", PNG_FILTER_NONE, SPNG_FILTER_CHOICE_NONE},
                            {"Sub", PNG_FILTER_SUB, SPNG_FILTER_CHOICE_SUB},
                            {"Up", PNG_FILTER_UP, SPNG_FILTER_CHOICE_UP},
                            {"Paeth", PNG_FILTER_PAETH, SPNG_FILTER_CHOICE_PAETH},
                            {"all (per-row choice)", PNG_ALL_FILTERS, SPNG_FILTER_CHOICE_ALL}};
  for (int level : {1, 6})
    for (const Filter& f : filters) {
      if (level == 6 && f.libpng != PNG_ALL_FILTERS) continue;
      const std::string setting = "level " + std::to_string(level) + ", filter " + f.name;
      row("libpng, " + setting + (level == 1 && f.libpng == PNG_FILTER_UP ? " (lfd now)" : ""), runs,
          [&] { write_libpng(im, level, f.libpng); });
      row("libspng, " + setting, runs, [&] { write_spng(im, level, f.spng); });
    }
  std::printf("\n| reader (of the level-1 Up file) | median [s] | min-max [s] | file [MB] |\n|---|---:|---:|---:|\n");
  write_libpng(im, 1, PNG_FILTER_UP);
  row("stb_image (lfd before)", runs, read_stb);
  row("libpng (lfd now)", runs, read_libpng);
  row("libspng", runs, read_spng);
  std::remove(kOut);
  return 0;
}
