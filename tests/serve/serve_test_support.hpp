#pragma once
// Fixtures of the serve tests: a served display from a real unit's visual.json, a small PNG
// quilt in memory, a temporary folder.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "serve/served_display.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace lfd::serve::test {

inline ServedDisplay fixture_display() {
  return served_display_from_file(0, lfd::test::fixture_calibration("LKG-PORT-portrait.visual.json"));
}

// A quilt whose pixels say where they are, so a decoded copy can be compared exactly.
inline Image8 pattern_quilt(int w, int h) {
  Image8 image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto* p = &image.pixels[(static_cast<size_t>(y) * w + x) * 3];
      p[0] = static_cast<uint8_t>(x * 7);
      p[1] = static_cast<uint8_t>(y * 5);
      p[2] = static_cast<uint8_t>((x + y) * 3);
    }
  return image;
}

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string t = (std::filesystem::temp_directory_path() / "lfd-serve-test-XXXXXX").string();
    path = mkdtemp(t.data());
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

inline std::vector<std::uint8_t> png_bytes(const Image8& image, const std::filesystem::path& dir) {
  const auto file = dir / "quilt.png";
  write_png(file, image);
  std::vector<std::uint8_t> bytes(std::filesystem::file_size(file));
  std::FILE* f = std::fopen(file.c_str(), "rb");
  const size_t n = std::fread(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  bytes.resize(n);
  return bytes;
}

}  // namespace lfd::serve::test
