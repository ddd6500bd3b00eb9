// Bad scene files fail with lfd::InputError naming the file and the problem, never a crash,
// a hang or an allocation sized by a lying header.
#include <gtest/gtest.h>
#include <zlib.h>
#include <zstd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "tests/scene/gzip_for_tests.hpp"
#include "tests/scene/scene_bad_input_fixture.hpp"
#include "scene/ply_writer.hpp"
#include "scene/gaussian_io.hpp"
#include "util/error.hpp"

namespace lfd::scene {
namespace {

namespace fs = std::filesystem;

class SceneBadInput : public SceneBadInputFixture {};

scene::GaussianScene two_gaussians(int degree = 1) {
  scene::GaussianScene s;
  s.sh_degree = degree;
  s.positions = {{0, 0, 0}, {1, 2, 3}};
  s.scales = {{0.1f, 0.2f, 0.3f}, {0.01f, 0.02f, 0.03f}};
  s.rotations = {{1, 0, 0, 0}, {0.5f, 0.5f, 0.5f, 0.5f}};
  s.opacities = {0.5f, 0.9f};
  s.sh.assign(2 * size_t(s.sh_coeffs()) * 3, 0.1f);
  return s;
}

std::string replace_first(std::string s, const std::string& from, const std::string& to) {
  s.replace(s.find(from), from.size(), to);
  return s;
}

using lfd::test::gzip;

// A 16-byte legacy SPZ header.
std::string spz_header(uint32_t version, uint32_t points, uint8_t degree, uint8_t flags = 0) {
  std::string h(16, '\0');
  const uint32_t magic = 0x5053474e;
  std::memcpy(h.data(), &magic, 4);
  std::memcpy(h.data() + 4, &version, 4);
  std::memcpy(h.data() + 8, &points, 4);
  h[12] = char(degree), h[13] = 12, h[14] = char(flags);
  return h;
}

TEST_F(SceneBadInput, MissingFile) { expect_rejected(dir_ / "absent.ply", "no such file"); }

TEST_F(SceneBadInput, EmptyFile) { expect_rejected(write("empty.ply", ""), "empty"); }

TEST_F(SceneBadInput, UnknownFormat) {
  expect_rejected(write("junk.bin", "hello world, not a scene"), "unrecognised");
}

TEST_F(SceneBadInput, TruncatedBinaryPly) {
  std::string ply = scene::encode_ply(two_gaussians());
  ply.resize(ply.size() - 10);
  expect_rejected(write("truncated.ply", ply), "truncated");
}

TEST_F(SceneBadInput, TruncatedAsciiPly) {
  std::string ply = scene::encode_ply(two_gaussians(), scene::PlyEncoding::Ascii);
  ply.resize(ply.size() - ply.size() / 4);
  expect_rejected(write("truncated_ascii.ply", ply), "truncated");
}

TEST_F(SceneBadInput, HeaderCountLargerThanData) {
  const std::string ply =
      replace_first(scene::encode_ply(two_gaussians()), "element vertex 2", "element vertex 3");
  expect_rejected(write("count.ply", ply), "truncated");
}

TEST_F(SceneBadInput, AbsurdCountFailsBeforeAllocating) {
  const std::string ply = replace_first(scene::encode_ply(two_gaussians()), "element vertex 2",
                                        "element vertex 18446744073709551615");
  expect_rejected(write("absurd.ply", ply), "vertex");
  const std::string ascii = replace_first(scene::encode_ply(two_gaussians(), scene::PlyEncoding::Ascii),
                                          "element vertex 2", "element vertex 4000000000000");
  expect_rejected(write("absurd_ascii.ply", ascii), "claims");
}

TEST_F(SceneBadInput, ElementWithRowsButNoPropertiesFailsFast) {
  // Found by fuzzing: nothing bounds the count of property-less rows, so it must be rejected.
  expect_rejected(write("empty_rows.ply", "ply\nformat ascii 1.0\nelement vertex 66600000000\n"
                                          "end_header\n2.4\n"),
                  "no properties");
}

TEST_F(SceneBadInput, ValueBeyondFloatRangeIsNotFinite) {
  std::string ply = scene::encode_ply(two_gaussians(0), scene::PlyEncoding::Ascii);
  ply = replace_first(ply, "end_header\n0 ", "end_header\n1e300 ");
  expect_rejected(write("huge.ply", ply), "position is not finite");
}

TEST_F(SceneBadInput, AsciiIntegerPropertyOutOfRange) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement chunk 1\nproperty uchar min_x\nend_header\n300\n";
  expect_rejected(write("range.compressed.ply", ply), "does not fit");
}

TEST_F(SceneBadInput, NaNValue) {
  scene::GaussianScene s = two_gaussians();
  s.positions[1][2] = std::numeric_limits<float>::quiet_NaN();
  expect_rejected(write("nan.ply", scene::encode_ply(s)), "position is not finite");
}

TEST_F(SceneBadInput, InfValueInAscii) {
  std::string ply = scene::encode_ply(two_gaussians(0), scene::PlyEncoding::Ascii);
  // The first value of the first row is x.
  ply = replace_first(ply, "end_header\n0 ", "end_header\ninf ");
  expect_rejected(write("inf.ply", ply), "position is not finite");
}

TEST_F(SceneBadInput, MissingProperty) {
  const std::string ply =
      replace_first(scene::encode_ply(two_gaussians()), "property float opacity", "property float opacitz");
  expect_rejected(write("missing.ply", ply), "no property 'opacity'");
}

TEST_F(SceneBadInput, SHCountMatchingNoDegree) {
  const std::string ply =
      replace_first(scene::encode_ply(two_gaussians()), "property float f_rest_8", "property float g_8");
  expect_rejected(write("sh.ply", ply), "f_rest");
}

TEST_F(SceneBadInput, BigEndianPlyIsAnUnknownLayout) {
  const std::string ply = replace_first(scene::encode_ply(two_gaussians()), "binary_little_endian",
                                        "binary_big_endian");
  expect_rejected(write("big.ply", ply), "not supported");
}

TEST_F(SceneBadInput, ListPropertyIsAnUnknownLayout) {
  const std::string ply = replace_first(scene::encode_ply(two_gaussians()), "property float nx",
                                        "property list uchar int nx");
  expect_rejected(write("list.ply", ply), "list");
}

TEST_F(SceneBadInput, ZeroQuaternion) {
  scene::GaussianScene s = two_gaussians();
  s.rotations[0] = {0, 0, 0, 0};
  expect_rejected(write("zero_q.ply", scene::encode_ply(s)), "zero length");
}

TEST_F(SceneBadInput, CompressedPlyWithTooFewChunks) {
  const std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement chunk 0\nproperty float min_x\n"
      "element vertex 300\nproperty uint packed_position\nend_header\n" +
      std::string(1200, '\0');
  expect_rejected(write("chunks.compressed.ply", ply), "chunks");
}

TEST_F(SceneBadInput, CompressedPlyMissingProperty) {
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement chunk 1\n";
  for (const char* n : {"min_x", "min_y", "min_z", "max_x", "max_y", "max_z"})
    ply += std::string("property float ") + n + "\n";
  ply += "element vertex 1\nproperty uint packed_position\nend_header\n";
  ply += std::string(6 * 4 + 4, '\0');
  expect_rejected(write("props.compressed.ply", ply), "min_scale_x");
}

TEST_F(SceneBadInput, SplatNotAMultipleOf32) {
  expect_rejected(write("short.splat", std::string(33, '\x80')), "multiple of 32");
}

TEST_F(SceneBadInput, SplatWithNaN) {
  std::string rec(32, '\x80');
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(rec.data() + 4, &nan, 4);
  expect_rejected(write("nan.splat", rec), "not finite");
}

TEST_F(SceneBadInput, SpzTruncatedGzip) {
  std::string data = gzip(spz_header(2, 100, 0) + std::string(100 * 19, '\x40'));
  data.resize(data.size() / 2);
  expect_rejected(write("truncated.spz", data), "truncated");
}

TEST_F(SceneBadInput, SpzCountLargerThanData) {
  const std::string data = gzip(spz_header(3, 5, 0) + std::string(3 * 20, '\x40'));
  expect_rejected(write("count.spz", data), "truncated");
}

TEST_F(SceneBadInput, SpzAbsurdCountFailsBeforeDecompressing) {
  const std::string data = gzip(spz_header(3, 200000000, 3));
  expect_rejected(write("absurd.spz", data), "claims");
}

TEST_F(SceneBadInput, SpzUnknownVersion) {
  expect_rejected(write("v9.spz", gzip(spz_header(9, 1, 0))), "version 9");
}

TEST_F(SceneBadInput, SpzRawCountLargerThanData) {
  expect_rejected(write("raw_count.spz", spz_header(3, 5, 0) + std::string(3 * 20, '\x40')),
                  "truncated");
}

TEST_F(SceneBadInput, SpzRawShorterThanItsHeader) {
  expect_rejected(write("raw_header.spz", spz_header(3, 1, 0).substr(0, 10)), "truncated");
}

TEST_F(SceneBadInput, SpzRawVersion1IsRefused) {
  expect_rejected(write("raw_v1.spz", spz_header(1, 1, 0) + std::string(15, '\x40')),
                  "version 1");
}

TEST_F(SceneBadInput, SpzGzipWithoutMagic) {
  expect_rejected(write("nomagic.spz", gzip(std::string(64, 'x'))), "magic");
}

TEST_F(SceneBadInput, SpzV4StreamSizeMismatch) {
  std::string h(32, '\0');
  const uint32_t magic = 0x5053474e, version = 4, points = 2, toc = 32;
  std::memcpy(h.data(), &magic, 4);
  std::memcpy(h.data() + 4, &version, 4);
  std::memcpy(h.data() + 8, &points, 4);
  h[13] = 12, h[15] = 5;
  std::memcpy(h.data() + 16, &toc, 4);
  // A TOC whose first stream claims 7 bytes where 2 points need 18.
  std::string table(5 * 16, '\0');
  const uint64_t compressed = 10, uncompressed = 7;
  std::memcpy(table.data(), &compressed, 8);
  std::memcpy(table.data() + 8, &uncompressed, 8);
  expect_rejected(write("v4.spz", h + table + std::string(10, '\0')), "need 18");
}

TEST_F(SceneBadInput, SpzV4CorruptZstdStream) {
  std::string h(32, '\0');
  const uint32_t magic = 0x5053474e, version = 4, points = 1, toc = 32;
  std::memcpy(h.data(), &magic, 4);
  std::memcpy(h.data() + 4, &version, 4);
  std::memcpy(h.data() + 8, &points, 4);
  h[13] = 12, h[15] = 5;
  std::memcpy(h.data() + 16, &toc, 4);
  const uint64_t sizes[5] = {9, 1, 3, 3, 4};
  std::string table, streams;
  for (uint64_t s : sizes) {
    const std::string junk(s + 4, '\x55');  // not a zstd frame
    const uint64_t c = junk.size();
    table.append(reinterpret_cast<const char*>(&c), 8);
    table.append(reinterpret_cast<const char*>(&s), 8);
    streams += junk;
  }
  expect_rejected(write("corrupt_v4.spz", h + table + streams), "zstd");
}

}  // namespace
}  // namespace lfd::scene
