// Bad SOG, glTF and .ksplat files (truncated, lying counts, huge image dimensions) fail with one
// line naming the file and the field, before any allocation sized by the lie.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/gaussian_io.hpp"
#include "tests/scene/scene_bad_input_fixture.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::scene {
namespace {

namespace fs = std::filesystem;
const fs::path kFormats = test::fixtures() / "scenes" / "formats";

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class SceneFormatsBadInput : public SceneBadInputFixture {
 protected:
  // A copy of the unpacked SOG fixture with meta.json edited by `edit`.
  fs::path sog_with(const std::function<void(nlohmann::json&)>& edit) {
    const fs::path d = dir_ / "sog";
    fs::create_directories(d);
    for (const auto& f : fs::directory_iterator(kFormats / "tabletop-sog"))
      fs::copy_file(f.path(), d / f.path().filename(), fs::copy_options::overwrite_existing);
    nlohmann::json meta = nlohmann::json::parse(read(d / "meta.json"));
    edit(meta);
    std::ofstream(d / "meta.json") << meta.dump();
    return d / "meta.json";
  }
};

// A lossless-WebP header (VP8L) claiming width x height, with no image data after it.
std::string webp_header(uint32_t width, uint32_t height) {
  std::string b = "RIFF____WEBPVP8L____";
  const uint32_t riff = 4 + 8 + 5, chunk = 5;
  std::memcpy(&b[4], &riff, 4);
  std::memcpy(&b[16], &chunk, 4);
  b.push_back(char(0x2f));
  const uint32_t bits = (width - 1) | (height - 1) << 14 | 1u << 28;
  b.append(reinterpret_cast<const char*>(&bits), 4);
  return b;
}

TEST_F(SceneFormatsBadInput, TruncatedSogArchive) {
  const std::string sog = read(kFormats / "tabletop.sog");
  expect_rejected(write("half.sog", sog.substr(0, sog.size() / 2)), "SOG");
}

TEST_F(SceneFormatsBadInput, SogCountBeyondTheImages) {
  expect_rejected(sog_with([](auto& m) { m["count"] = 100000; }), "fewer than the 100000 Gaussians");
  expect_rejected(sog_with([](auto& m) { m["count"] = 1e15; }), "count must be a whole number");
}

TEST_F(SceneFormatsBadInput, SogImageWithHugeDimensions) {
  const fs::path meta = sog_with([](auto&) {});
  std::ofstream(meta.parent_path() / "quats.webp", std::ios::binary) << webp_header(16384, 16384);
  expect_rejected(meta, "16384x16384 pixels, more than");
}

TEST_F(SceneFormatsBadInput, SogFieldsOfTheWrongShape) {
  expect_rejected(sog_with([](auto& m) { m["scales"]["codebook"] = {1, 2}; }),
                  "scales.codebook must be an array of 256 numbers");
  expect_rejected(sog_with([](auto& m) { m["shN"]["count"] = 1000000; }), "shN.count");
  expect_rejected(sog_with([](auto& m) { m["version"] = 3; }), "SOG version 3");
  expect_rejected(sog_with([](auto& m) { m["means"]["files"] = {"../means_l.webp"}; }), "missing");
}

// The GLB fixture with its JSON chunk replaced by `edit` of it.
std::string glb_with(const std::function<void(nlohmann::json&)>& edit) {
  const std::string glb = read(kFormats / "tabletop.glb");
  uint32_t json_bytes;
  std::memcpy(&json_bytes, &glb[12], 4);
  nlohmann::json j = nlohmann::json::parse(glb.substr(20, json_bytes));
  edit(j);
  std::string text = j.dump();
  while (text.size() % 4) text += ' ';
  const std::string bin = glb.substr(20 + json_bytes);
  std::string out = glb.substr(0, 12);
  const uint32_t length = uint32_t(text.size()), total = uint32_t(12 + 8 + text.size() + bin.size());
  std::memcpy(&out[8], &total, 4);
  out.append(reinterpret_cast<const char*>(&length), 4);
  out += "JSON" + text + bin;
  return out;
}

TEST_F(SceneFormatsBadInput, TruncatedGlb) {
  const std::string glb = read(kFormats / "tabletop.glb");
  expect_rejected(write("half.glb", glb.substr(0, glb.size() / 2)), "glTF");
}

TEST_F(SceneFormatsBadInput, GlbAccessorCountBeyondItsBuffer) {
  expect_rejected(write("count.glb", glb_with([](auto& j) { j["accessors"][0]["count"] = 100000000; })),
                  "do not fit in their buffer view");
}

TEST_F(SceneFormatsBadInput, GlbWithoutTheExtensionOrItsAttributes) {
  expect_rejected(write("plain.glb", glb_with([](auto& j) {
                    j["meshes"][0]["primitives"][0].erase("extensions");
                  })),
                  "no primitive with the KHR_gaussian_splatting extension");
  expect_rejected(write("noscale.glb", glb_with([](auto& j) {
                    j["meshes"][0]["primitives"][0]["attributes"].erase("KHR_gaussian_splatting:SCALE");
                  })),
                  "no KHR_gaussian_splatting:SCALE attribute");
}

TEST_F(SceneFormatsBadInput, TruncatedKsplat) {
  const std::string k = read(kFormats / "tabletop-c1.ksplat");
  expect_rejected(write("half.ksplat", k.substr(0, k.size() - 100)), "truncated .ksplat");
  expect_rejected(write("header.ksplat", k.substr(0, 1000)), "truncated .ksplat");
}

TEST_F(SceneFormatsBadInput, KsplatLyingCounts) {
  std::string k = read(kFormats / "tabletop-c2.ksplat");
  uint32_t count;
  std::memcpy(&count, &k[16], 4);
  std::string more = k;
  const uint32_t lie = count + 1;
  std::memcpy(&more[16], &lie, 4);
  expect_rejected(write("count.ksplat", more), "header claims 401 Gaussians");
  std::string sections = k;
  const uint32_t many = 1u << 30;
  std::memcpy(&sections[4], &many, 4);
  expect_rejected(write("sections.ksplat", sections), "claims 1073741824 sections");
  std::string capacity = k;
  std::memcpy(&capacity[4096 + 4], &many, 4);  // the first section's capacity
  expect_rejected(write("capacity.ksplat", capacity), "truncated .ksplat: section 0");
}

}  // namespace
}  // namespace lfd::scene
