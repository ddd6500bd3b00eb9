// Scene formats against the reference tools (tests/data/scenes/formats/README.md): one
// 400-Gaussian scene with SH degree 2, written as SOG v2 and GLB by playcanvas/splat-transform
// 3.7.0 and as .ksplat (levels 0-2) by mkkellogg/GaussianSplats3D 0.4.7, renders within 50 dB
// of the same scene as the reference tool decodes it back to PLY. SOG v1 (which no reference
// tool available here writes any more) is written by the encoder below, from the formulas of
// splat-transform's read-sog-v1.ts, and must decode to within half a quantisation step.
#include <gtest/gtest.h>
#include <webp/encode.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/rasterizer_cpu.hpp"
#include "scene/gaussian_io.hpp"
#include "tests/test_data.hpp"

namespace lfd::render {
namespace {

const std::filesystem::path kFormats = test::fixtures() / "scenes" / "formats";

// The scene rendered by the reference rasterizer from the camera that frames `framing`.
ImageF render(const scene::GaussianScene& scene, const scene::GaussianScene& framing) {
  const Camera camera = camera_from_spec(frame_scene(framing), 256, 192);
  const RasterImage r = rasterize(scene, camera);
  ImageF image(r.width, r.height, 3);
  image.pixels = r.rgb;
  return image;
}

double psnr_against(const std::string& file, const std::string& truth_file) {
  const scene::GaussianScene truth = scene::load_gaussian_scene(kFormats / truth_file);
  const scene::GaussianScene scene = scene::load_gaussian_scene(kFormats / file);
  EXPECT_EQ(scene.size(), truth.size()) << file;
  EXPECT_EQ(scene.sh_degree, truth.sh_degree) << file;
  const ImageF expected = render(truth, truth);
  // The comparison means something only if the frame shows the scene: most pixels covered.
  size_t covered = 0;
  for (size_t k = 0; k < expected.pixels.size(); k += 3)
    covered += expected.pixels[k] + expected.pixels[k + 1] + expected.pixels[k + 2] > 0.05f;
  EXPECT_GT(covered, expected.pixels.size() / 3 / 2) << file;
  const double p = psnr(render(scene, truth), expected);
  ::testing::Test::RecordProperty(file, std::to_string(p));
  std::printf("%s: %.1f dB\n", file.c_str(), p);
  return p;
}

TEST(SceneFormatsReference, SogArchiveMatchesSplatTransformsDecode) {
  EXPECT_GE(psnr_against("tabletop.sog", "tabletop.sog.decoded.ply"), 50.0);
}

TEST(SceneFormatsReference, UnpackedSogMatchesSplatTransformsDecode) {
  EXPECT_GE(psnr_against("tabletop-sog/meta.json", "tabletop.sog.decoded.ply"), 50.0);
}

TEST(SceneFormatsReference, GlbMatchesTheSourcePly) {
  EXPECT_GE(psnr_against("tabletop.glb", "tabletop.ply"), 50.0);
  // Float attributes: the half turn about z between glTF and the PLY frame must undo exactly,
  // SH signs included (a wrong parity would still render close at this SH magnitude).
  const scene::GaussianScene ply = scene::load_gaussian_scene(kFormats / "tabletop.ply");
  const scene::GaussianScene glb = scene::load_gaussian_scene(kFormats / "tabletop.glb");
  ASSERT_EQ(glb.sh.size(), ply.sh.size());
  for (size_t i = 0; i < ply.size(); ++i)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(glb.positions[i][a], ply.positions[i][a], 1e-6f);
  for (size_t k = 0; k < ply.sh.size(); ++k) ASSERT_NEAR(glb.sh[k], ply.sh[k], 1e-6f) << k;
}

TEST(SceneFormatsReference, KsplatLevelsMatchSplatTransformsDecode) {
  for (int level = 0; level < 3; ++level) {
    const std::string f = "tabletop-c" + std::to_string(level) + ".ksplat";
    EXPECT_GE(psnr_against(f, f + ".decoded.ply"), 50.0) << f;
  }
}

// ---- SOG version 1, written here ----

struct Quantiser {
  float lo = 0, hi = 0;
  void add(float v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  float step(int levels) const { return (hi - lo) / float(levels); }
  int code(float v, int levels) const {
    return hi > lo ? int(std::lround((v - lo) / (hi - lo) * float(levels))) : 0;
  }
};

float log_transform(float x) { return std::copysign(std::log(std::fabs(x) + 1.0f), x); }
float logit(float o) { return std::log(o / (1.0f - o)); }

void write_webp(const std::filesystem::path& path, const std::vector<uint8_t>& rgba, int w, int h) {
  uint8_t* out = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(rgba.data(), w, h, w * 4, &out);
  ASSERT_GT(size, 0u);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(out), std::streamsize(size));
  WebPFree(out);
}

struct SogV1Steps {
  std::array<Quantiser, 3> means, scales;
  std::array<Quantiser, 4> sh0;
  Quantiser rest;
};

// Writes `s` as an unpacked SOG v1 (meta.json without a version, per-channel lerps) into `dir`.
SogV1Steps write_sog_v1(const scene::GaussianScene& s, const std::filesystem::path& dir) {
  SogV1Steps q;
  const size_t n = s.size(), coeffs = size_t(s.sh_coeffs()), rest = coeffs - 1;
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      q.means[a].add(log_transform(s.positions[i][a]));
      q.scales[a].add(std::log(s.scales[i][a]));
      q.sh0[a].add(s.sh_of(i)[a]);
    }
    q.sh0[3].add(logit(s.opacities[i]));
    for (size_t k = 3; k < coeffs * 3; ++k) q.rest.add(s.sh_of(i)[k]);
  }
  const int w = 16, h = int((n + 15) / 16);
  std::vector<uint8_t> lo(size_t(w * h) * 4, 255), hi = lo, quats = lo, scales = lo, sh0 = lo, labels = lo;
  const int pw = int(64 * rest), ph = int((n + 63) / 64);
  std::vector<uint8_t> palette(size_t(pw * ph) * 4, 255);
  for (size_t i = 0; i < n; ++i) {
    uint8_t* p = &lo[i * 4];
    for (int a = 0; a < 3; ++a) {
      const int m = q.means[a].code(log_transform(s.positions[i][a]), 65535);
      p[a] = uint8_t(m & 255), hi[i * 4 + size_t(a)] = uint8_t(m >> 8);
      scales[i * 4 + size_t(a)] = uint8_t(q.scales[a].code(std::log(s.scales[i][a]), 255));
      sh0[i * 4 + size_t(a)] = uint8_t(q.sh0[a].code(s.sh_of(i)[a], 255));
    }
    sh0[i * 4 + 3] = uint8_t(q.sh0[3].code(logit(s.opacities[i]), 255));
    auto r = s.rotations[i];
    int largest = 0;
    for (int k = 1; k < 4; ++k) if (std::fabs(r[k]) > std::fabs(r[largest])) largest = k;
    if (r[largest] < 0) for (float& v : r) v = -v;
    for (int k = 0, j = 0; k < 4; ++k)
      if (k != largest) quats[i * 4 + size_t(j++)] = uint8_t(std::lround((r[k] * std::sqrt(2.0f) + 1) / 2 * 255));
    quats[i * 4 + 3] = uint8_t(252 + largest);
    labels[i * 4] = uint8_t(i & 255), labels[i * 4 + 1] = uint8_t(i >> 8), labels[i * 4 + 2] = 0;
    for (size_t k = 0; k < rest; ++k)
      for (int ch = 0; ch < 3; ++ch)
        palette[((i / 64) * size_t(pw) + (i % 64) * rest + k) * 4 + size_t(ch)] =
            uint8_t(q.rest.code(s.sh_of(i)[(k + 1) * 3 + size_t(ch)], 255));
  }
  std::filesystem::create_directories(dir);
  write_webp(dir / "means_l.webp", lo, w, h);
  write_webp(dir / "means_u.webp", hi, w, h);
  write_webp(dir / "quats.webp", quats, w, h);
  write_webp(dir / "scales.webp", scales, w, h);
  write_webp(dir / "sh0.webp", sh0, w, h);
  write_webp(dir / "shN_centroids.webp", palette, pw, ph);
  write_webp(dir / "shN_labels.webp", labels, w, h);
  auto range = [](const auto& qs) {
    nlohmann::json mins = nlohmann::json::array(), maxs = nlohmann::json::array();
    for (const auto& x : qs) mins.push_back(x.lo), maxs.push_back(x.hi);
    return std::pair{mins, maxs};
  };
  nlohmann::json meta;
  meta["means"] = {{"shape", {n, 3}}, {"mins", range(q.means).first}, {"maxs", range(q.means).second},
                   {"files", {"means_l.webp", "means_u.webp"}}};
  meta["scales"] = {{"mins", range(q.scales).first}, {"maxs", range(q.scales).second}, {"files", {"scales.webp"}}};
  meta["quats"] = {{"files", {"quats.webp"}}};
  meta["sh0"] = {{"mins", range(q.sh0).first}, {"maxs", range(q.sh0).second}, {"files", {"sh0.webp"}}};
  meta["shN"] = {{"mins", q.rest.lo}, {"maxs", q.rest.hi}, {"files", {"shN_centroids.webp", "shN_labels.webp"}}};
  std::ofstream(dir / "meta.json") << meta.dump();
  return q;
}

TEST(SceneFormatsReference, SogVersion1DecodesToHalfAQuantisationStep) {
  const scene::GaussianScene s = scene::load_gaussian_scene(kFormats / "tabletop.ply");
  const auto dir = std::filesystem::path(::testing::TempDir()) / "lfd-sog-v1";
  std::filesystem::remove_all(dir);
  const SogV1Steps q = write_sog_v1(s, dir);
  const scene::GaussianScene v1 = scene::load_gaussian_scene(dir / "meta.json");
  ASSERT_EQ(v1.size(), s.size());
  ASSERT_EQ(v1.sh_degree, s.sh_degree);
  const float slack = 1.001f;  // float rounding on top of the half step
  for (size_t i = 0; i < s.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const float x = s.positions[i][a];
      EXPECT_NEAR(v1.positions[i][a], x, slack * (std::fabs(x) + 1) * q.means[a].step(65535) / 2 + 1e-6f);
      EXPECT_NEAR(std::log(v1.scales[i][a]), std::log(s.scales[i][a]), slack * q.scales[a].step(255) / 2 + 1e-6f);
      EXPECT_NEAR(v1.sh_of(i)[a], s.sh_of(i)[a], slack * q.sh0[a].step(255) / 2 + 1e-6f);
    }
    EXPECT_NEAR(logit(v1.opacities[i]), logit(s.opacities[i]), slack * q.sh0[3].step(255) / 2 + 1e-4f);
    for (size_t k = 3; k < size_t(s.sh_coeffs()) * 3; ++k)
      EXPECT_NEAR(v1.sh_of(i)[k], s.sh_of(i)[k], slack * q.rest.step(255) / 2 + 1e-6f);
    float dot = 0;
    for (int k = 0; k < 4; ++k) dot += v1.rotations[i][k] * s.rotations[i][k];
    EXPECT_GT(std::fabs(dot), 0.9999f);  // 8-bit components: about 0.3 degrees
  }
}

}  // namespace
}  // namespace lfd::render
