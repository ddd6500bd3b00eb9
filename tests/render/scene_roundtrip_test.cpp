// scene::save_ply writes what scene::load_gaussian_scene reads back: binary and ASCII PLY, all SH degrees; SPZ v4
// (zstd streams) and raw v2/v3 (no gzip layer) decode exactly like the equivalent gzip file.
#include <unistd.h>
#include <gtest/gtest.h>
#include <zlib.h>
#include <zstd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/scene/gzip_for_tests.hpp"
#include "scene/ply_writer.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "scene/spz_writer.hpp"
#include "tests/test_data.hpp"

namespace lfd::render {
namespace {

namespace fs = std::filesystem;

fs::path temp_path(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("lfd_scene_roundtrip_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_same(const scene::GaussianScene& a, const scene::GaussianScene& b, float tolerance) {
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.sh_degree, b.sh_degree);
  for (size_t i = 0; i < a.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a.positions[i][k], b.positions[i][k], tolerance);
      EXPECT_NEAR(a.scales[i][k], b.scales[i][k], tolerance * a.scales[i][k]);
    }
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.rotations[i][k], b.rotations[i][k], tolerance);
    EXPECT_NEAR(a.opacities[i], b.opacities[i], tolerance);
  }
  for (size_t k = 0; k < a.sh.size(); ++k) ASSERT_NEAR(a.sh[k], b.sh[k], tolerance) << k;
}

class PlyRoundTrip : public ::testing::TestWithParam<int> {};

TEST_P(PlyRoundTrip, BinaryPlyReadsBackWhatWasSaved) {
  const scene::GaussianScene scene = generate_scene({"tabletop", 500, 3, GetParam()});
  const fs::path p = temp_path("binary_" + std::to_string(GetParam()) + ".ply");
  scene::save_ply(p, scene);
  expect_same(scene, scene::load_gaussian_scene(p), 1e-5f);
}

TEST_P(PlyRoundTrip, AsciiPlyReadsBackAndResavesAsBinary) {
  const scene::GaussianScene scene = generate_scene({"corridor", 300, 4, GetParam()});
  const fs::path ascii = temp_path("ascii_" + std::to_string(GetParam()) + ".ply");
  const std::string text = scene::encode_ply(scene, scene::PlyEncoding::Ascii);
  std::ofstream(ascii, std::ios::binary).write(text.data(), std::streamsize(text.size()));
  const scene::GaussianScene from_ascii = scene::load_gaussian_scene(ascii);
  expect_same(scene, from_ascii, 1e-5f);
  const fs::path binary = temp_path("from_ascii_" + std::to_string(GetParam()) + ".ply");
  scene::save_ply(binary, from_ascii);
  expect_same(from_ascii, scene::load_gaussian_scene(binary), 1e-6f);
}

INSTANTIATE_TEST_SUITE_P(AllShDegrees, PlyRoundTrip, ::testing::Values(0, 1, 2, 3));

TEST(PlyRoundTrip, PropertiesAreFoundByNameInAnyOrder) {
  const scene::GaussianScene scene = generate_scene({"tabletop", 20, 5, 1});
  std::string ply = scene::encode_ply(scene, scene::PlyEncoding::Ascii);
  // Swap x and z in the header only: the reader must then return swapped columns.
  ply.replace(ply.find("property float x\n"), 17, "property float Q\n");
  ply.replace(ply.find("property float z\n"), 17, "property float x\n");
  ply.replace(ply.find("property float Q\n"), 17, "property float z\n");
  const fs::path p = temp_path("reordered.ply");
  std::ofstream(p, std::ios::binary) << ply;
  const scene::GaussianScene swapped = scene::load_gaussian_scene(p);
  for (size_t i = 0; i < scene.size(); ++i) {
    EXPECT_FLOAT_EQ(swapped.positions[i][0], scene.positions[i][2]);
    EXPECT_FLOAT_EQ(swapped.positions[i][2], scene.positions[i][0]);
  }
}

TEST(PlyRoundTrip, SaveIsAtomicAndLeavesNoTemporaryFiles) {
  const fs::path dir = temp_path("atomic");
  fs::create_directories(dir);
  scene::save_ply(dir / "scene.ply", generate_scene({"tabletop", 50, 1, 0}));
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
}

std::string gunzip(const std::string& data) {
  z_stream z{};
  inflateInit2(&z, 16 + MAX_WBITS);
  std::string out(1 << 20, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = uInt(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  inflate(&z, Z_FINISH);
  out.resize(z.total_out);
  inflateEnd(&z);
  return out;
}

TEST(SpzContainers, V4ZstdStreamsDecodeLikeTheV3GzipFile) {
  const fs::path v3 = test::fixture_scene("three-points.spz");
  const std::string raw = gunzip(read_bytes(v3));
  // 16-byte header + 3 Gaussians x (9 position + 1 alpha + 3 colour + 3 scale + 4 rotation + 45 SH
  // bytes at degree 3) = 16 + 27 + 3 + 9 + 9 + 12 + 135 = 211.
  ASSERT_EQ(raw.size(), 211u);
  const uint32_t n = 3;
  const uint64_t sizes[6] = {n * 9, n, n * 3, n * 3, n * 4, n * 45};
  std::string header(32, '\0');
  std::memcpy(header.data(), raw.data(), 16);  // magic, version, count, degree, bits, flags
  const uint32_t version = 4, toc = 32;
  std::memcpy(header.data() + 4, &version, 4);
  header[15] = 6;  // stream count
  std::memcpy(header.data() + 16, &toc, 4);
  std::string table, streams;
  size_t offset = 16;
  for (uint64_t size : sizes) {
    std::string frame(ZSTD_compressBound(size), '\0');
    frame.resize(ZSTD_compress(frame.data(), frame.size(), raw.data() + offset, size, 3));
    offset += size;
    const uint64_t compressed = frame.size();
    table.append(reinterpret_cast<const char*>(&compressed), 8);
    table.append(reinterpret_cast<const char*>(&size), 8);
    streams += frame;
  }
  const fs::path v4 = temp_path("three-points-v4.spz");
  std::ofstream(v4, std::ios::binary) << header + table + streams;
  expect_same(scene::load_gaussian_scene(v3), scene::load_gaussian_scene(v4), 0.0f);
}

using lfd::test::gzip;

// The v3 fixture's payload as version 2: rotations re-encoded as v2 bytes, xyz of the
// file-frame (RUB) quaternion with w >= 0, byte = (c + 1) * 127.5.
std::string v2_payload(const std::string& v3_payload, const scene::GaussianScene& v3_scene) {
  std::string v2 = v3_payload.substr(0, 16 + 27 + 3 + 9 + 9);
  v2[4] = 2;
  for (size_t i = 0; i < 3; ++i) {
    auto q = v3_scene.rotations[i];  // RDF (w, x, y, z)
    const float sign = q[0] < 0 ? -1.0f : 1.0f;
    const float rub_xyz[3] = {sign * q[1], -sign * q[2], -sign * q[3]};
    for (float c : rub_xyz) v2 += char(uint8_t(std::lround((c + 1.0f) * 127.5f)));
  }
  return v2 + v3_payload.substr(16 + 27 + 3 + 9 + 9 + 12);
}

TEST(SpzContainers, V2ThreeByteRotationsDecodeLikeV3) {
  const fs::path v3 = test::fixture_scene("three-points.spz");
  const scene::GaussianScene expected = scene::load_gaussian_scene(v3);
  const std::string raw = gunzip(read_bytes(v3));
  ASSERT_EQ(raw.size(), 211u);
  const fs::path path = temp_path("three-points-v2.spz");
  std::ofstream(path, std::ios::binary) << gzip(v2_payload(raw, expected));
  const scene::GaussianScene got = scene::load_gaussian_scene(path);
  ASSERT_EQ(got.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(got.positions[i], expected.positions[i]);
    float dot = 0;
    for (int k = 0; k < 4; ++k) dot += got.rotations[i][k] * expected.rotations[i][k];
    EXPECT_GT(std::fabs(dot), 0.9999f) << "Gaussian " << i;
  }
  EXPECT_EQ(got.sh, expected.sh);
}

// The writer's payload without its gzip layer (PlayCanvas splat-transform reads and writes
// such files): the scene of the gzip file bit for bit, and the PLY it was written from to
// SPZ's quantisation (tests/render/scene_formats_test.cpp has each attribute's bound).
TEST(SpzContainers, RawV3PayloadReadsLikeTheGzipFile) {
  const scene::GaussianScene truth = scene::load_gaussian_scene(test::fixture_scene("three-points.ply"));
  const std::string gzipped = scene::encode_spz(truth);
  const std::string raw = gunzip(gzipped);
  ASSERT_EQ(raw.substr(0, 4), "NGSP");
  ASSERT_EQ(raw.size(), 211u);  // reference section 8: 16 + 27 + 3 + 9 + 9 + 12 + 135
  const fs::path gz = temp_path("three-points-written.spz");
  const fs::path plain = temp_path("three-points-raw.spz");
  std::ofstream(gz, std::ios::binary) << gzipped;
  std::ofstream(plain, std::ios::binary) << raw;
  const scene::GaussianScene got = scene::load_gaussian_scene(plain);
  expect_same(scene::load_gaussian_scene(gz), got, 0.0f);
  for (size_t i = 0; i < truth.size(); ++i) {
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(got.positions[i][a], truth.positions[i][a], 0.6f / 4096);
    EXPECT_NEAR(got.opacities[i], truth.opacities[i], 0.6f / 255);
  }
}

TEST(SpzContainers, RawV2PayloadReadsLikeTheGzipFile) {
  const fs::path v3 = test::fixture_scene("three-points.spz");
  const std::string v2 = v2_payload(gunzip(read_bytes(v3)), scene::load_gaussian_scene(v3));
  const fs::path gz = temp_path("three-points-v2-gzip.spz");
  const fs::path plain = temp_path("three-points-v2-raw.spz");
  std::ofstream(gz, std::ios::binary) << gzip(v2);
  std::ofstream(plain, std::ios::binary) << v2;
  expect_same(scene::load_gaussian_scene(gz), scene::load_gaussian_scene(plain), 0.0f);
}

}  // namespace
}  // namespace lfd::render
