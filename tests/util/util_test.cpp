#include <fstream>

#include <gtest/gtest.h>

#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

TEST(Image, PngRoundTripIsExact) {
  const auto dir = test::temp_dir("util_png");
  Image8 img(7, 5, 3);
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t(i * 37);
  write_png(dir / "a.png", img);
  const Image8 back = read_image(dir / "a.png", 3);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.pixels, img.pixels);
}

TEST(Image, MissingOrCorruptFilesNameTheFile) {
  const auto dir = test::temp_dir("util_bad_png");
  try {
    read_image(dir / "missing.png");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
  }
  std::ofstream(dir / "junk.png") << "not an image";
  try {
    read_image(dir / "junk.png");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("junk.png"), std::string::npos);
  }
}

TEST(Image, FloatConversionRoundsAndClamps) {
  ImageF f(2, 1, 1);
  f.pixels = {-0.5f, 0.5f};
  const Image8 b = to_uint8(f);
  EXPECT_EQ(b.pixels[0], 0);
  EXPECT_EQ(b.pixels[1], 128);
}

TEST(AtomicFile, AFailedWriteLeavesNothingBehind) {
  const auto dir = test::temp_dir("util_atomic");
  write_text_atomic(dir / "keep.txt", "old");
  EXPECT_THROW(write_file_atomic(dir / "keep.txt",
                                 [](const std::filesystem::path& tmp) {
                                   std::ofstream(tmp) << "half";
                                   throw std::runtime_error("disk full");
                                 }),
               std::runtime_error);
  EXPECT_EQ(read_text_file(dir / "keep.txt"), "old");
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}

TEST(AtomicFile, GuardOverwriteNeedsForceAndKeepsABackup) {
  const auto dir = test::temp_dir("util_guard");
  write_text_atomic(dir / "c.json", "v1");
  EXPECT_THROW(guard_overwrite(dir / "c.json", false), InputError);
  guard_overwrite(dir / "c.json", true);
  EXPECT_EQ(read_text_file(dir / "c.json.bak"), "v1");
  EXPECT_NO_THROW(guard_overwrite(dir / "new.json", false));
}

}  // namespace
}  // namespace lfd
