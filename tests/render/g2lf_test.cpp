// G2LF against the per-view baseline on a small random scene (45 views of 128x128).
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "render/g2lf.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render_test_scenes.hpp"
#include "util/error.hpp"

namespace lfd::render {
namespace {

struct Fixture {
  scene::GaussianScene scene = testing::random_cloud(4000, 2.5f, 5.0f, 7);
  QuiltGeometry geometry;
  QuiltLayout layout;
  ImageF baseline;
  Fixture() {
    const Camera base = make_look_at_camera({0, 0, 0}, {0, 0, 3.5f}, {0, 1, 0}, 0.6f, 128, 128);
    geometry = make_quilt_geometry(base, 3.5f, 40.0f, 45);
    layout = make_quilt_layout(geometry, 5, 9);
    baseline = render_quilt_per_view(scene, geometry, layout);
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

double g2lf_psnr(const G2lfOptions& o) {
  const Fixture& f = fixture();
  return psnr(render_quilt_g2lf(f.scene, f.geometry, f.layout, o), f.baseline);
}

TEST(G2lf, ManyChunksFinePlanesBilinearMatchThePerViewQuilt) {
  G2lfOptions o;
  o.chunks = 256;
  o.plane_scale = 2;
  o.filter = PlaneFilter::kBilinear;
  // Moving the reference camera back covers the near field the outer views see (paper D_shift).
  o.d_shift = 1.5f;
  const double p_u8 = g2lf_psnr(o);
  o.precision = PlanePrecision::kF32;
  const double p_f32 = g2lf_psnr(o);
  RecordProperty("psnr_u8", std::to_string(p_u8));
  RecordProperty("psnr_f32", std::to_string(p_f32));
  std::printf("G2LF 256 chunks, P_s 2, bilinear: PSNR u8 %.2f dB, f32 %.2f dB\n", p_u8, p_f32);
  EXPECT_GT(p_u8, 30.0);
  EXPECT_GT(p_f32, 30.0);
}

TEST(G2lf, FewerChunksLoseQuality) {
  G2lfOptions many, few;
  many.chunks = 128;
  few.chunks = 4;
  many.d_shift = few.d_shift = 0.5f;
  const double p_many = g2lf_psnr(many), p_few = g2lf_psnr(few);
  std::printf("G2LF nearest P_s 1: 128 chunks %.2f dB, 4 chunks %.2f dB\n", p_many, p_few);
  EXPECT_GT(p_many, p_few + 1.0);
}

// The skeleton (render/sweeping_plane_pipeline.hpp) adds nothing to the stages: the quilt and
// the stats are those of binning, planes and swizzle called one after another, and the default
// D_shift puts the reference camera at the base camera.
TEST(G2lf, QuiltIsItsStagesOneAfterAnother) {
  const Fixture& f = fixture();
  G2lfOptions o;
  o.chunks = 12;
  o.filter = PlaneFilter::kBilinear;
  const ReferenceCamera ref = reference_camera(o, f.geometry);
  EXPECT_LT(glm::length(ref.camera.position_world - f.geometry.base.position_world), 1e-5f);
  const DepthChunks chunks = bin_by_depth(f.scene, f.geometry, ref, o.chunks, o.binning);
  RasterSettings plane_settings;
  plane_settings.dilation_px2 =
      adaptive_filter_variance(f.geometry, ref, o.plane_scale, plane_settings.dilation_px2);
  const SweepingPlanes planes =
      render_sweeping_planes(f.scene, f.geometry, ref, chunks, o.precision, plane_settings);
  const glm::vec3 background{0.1f, 0.2f, 0.3f};
  ImageF by_stages(f.layout.width, f.layout.height, 3, 0.0f);
  swizzle_blend(planes, f.geometry, ref, f.layout, o.filter, background, by_stages);

  RasterSettings settings;
  settings.background = background;
  G2lfStats stats;
  const ImageF quilt = render_quilt_g2lf(f.scene, f.geometry, f.layout, o, settings, &stats);
  EXPECT_TRUE(quilt.pixels == by_stages.pixels);
  size_t binned = 0;
  for (const auto& m : chunks.members) binned += m.size();
  EXPECT_EQ(stats.gaussians_in_frustum, binned);
  EXPECT_EQ(stats.planes, planes.count);
  EXPECT_EQ(stats.plane_bytes, planes.bytes());
}

TEST(G2lf, DepthChunksAreQuantilesWithMedianPlanes) {
  const Fixture& f = fixture();
  const ReferenceCamera ref = make_reference_camera(f.geometry, 0.5f, 1);
  const DepthChunks c = bin_by_depth(f.scene, f.geometry, ref, 10);
  ASSERT_EQ(c.members.size(), 10u);
  size_t total = 0;
  for (size_t k = 0; k < c.members.size(); ++k) {
    total += c.members[k].size();
    if (k > 0) EXPECT_GT(c.plane_depth[k], c.plane_depth[k - 1]);
    EXPECT_LE(c.members[k].size(), c.members[0].size() + 1);
    EXPECT_GE(c.members[k].size() + 1, c.members[0].size());
  }
  EXPECT_GT(total, f.scene.size() / 2);
  EXPECT_LE(total, f.scene.size());
}

TEST(G2lf, SingleGaussianOnTheFocalPlaneLandsOnTheSamePixelInEveryView) {
  scene::GaussianScene s;
  testing::add_gaussian(s, {0, 0, 3.5f}, {0.02f, 0.02f, 0.02f}, 0.9f, {1, 1, 1});
  const Fixture& f = fixture();
  G2lfOptions o;
  o.chunks = 1;
  const ImageF q = render_quilt_g2lf(s, f.geometry, f.layout, o);
  for (int j : {0, 22, 44}) {
    const ImageF v = extract_view(q, f.layout, j);
    EXPECT_GT(v.at(64, 64, 0) + v.at(63, 63, 0), 0.5f) << j;
    EXPECT_LT(v.at(40, 64, 0), 0.01f) << j;
  }
}

TEST(G2lf, OptionsAreChecked) {
  G2lfOptions o;
  o.chunks = 0;
  EXPECT_THROW(o.check(), InputError);
  o = {};
  o.plane_scale = 0;
  EXPECT_THROW(o.check(), InputError);
  o = {};
  o.d_shift = std::nanf("");
  EXPECT_THROW(o.check(), InputError);
  EXPECT_THROW(parse_plane_filter("cubic"), InputError);
  EXPECT_THROW(parse_plane_precision("f16"), InputError);
  EXPECT_THROW(parse_chunk_binning("disparity"), InputError);
  EXPECT_EQ(parse_chunk_binning("mixed"), ChunkBinning::kMixed);
}

TEST(G2lf, OptionErrorsNameTheFieldNotAFlag) {
  G2lfOptions o;
  o.chunks = 0;
  try {
    o.check();
    FAIL() << "chunks = 0 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("G2LF options: chunks"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
  }
}

TEST(G2lf, ShiftBeyondDForwardIsRefusedNotRendered) {
  const Fixture& f = fixture();
  const float d_forward = make_reference_camera(f.geometry, 0.0f, 1).d_forward;
  G2lfOptions o;
  o.chunks = 4;
  o.d_shift = 2.0f * d_forward;  // reference camera behind the base camera
  EXPECT_THROW(o.check(f.geometry), InputError);
  try {
    render_quilt_g2lf(f.scene, f.geometry, f.layout, o);
    FAIL() << "D_shift " << o.d_shift << " > D_forward " << d_forward << " was rendered";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("d_shift"), std::string::npos) << what;
    EXPECT_NE(what.find("D_forward"), std::string::npos) << what;
  }
  o.d_shift = d_forward;  // at the base camera: the largest allowed
  EXPECT_NO_THROW(o.check(f.geometry));
  o.d_shift = -1.0f;      // the default: D_forward
  EXPECT_NO_THROW(o.check(f.geometry));
}

// A dense cluster at depth 3.3-3.7 (around the focal plane) in front of a sparse background spread over depth 5-40: the
// case (few large background Gaussians covering much of the image) where count quantiles put
// the whole background on one plane.
scene::GaussianScene cluster_before_sparse_background() {
  scene::GaussianScene s = testing::random_cloud(2000, 3.3f, 3.7f, 7);
  for (int i = 0; i < 60; ++i) {
    const float z = 5.0f + 35.0f * float(i) / 59.0f;
    const float x = 0.35f * z * (float((i * 37) % 11) / 5.0f - 1.0f), y = 0.35f * z * (float((i * 17) % 7) / 3.0f - 1.0f);
    testing::add_gaussian(s, {x, y, z}, {0.08f * z, 0.08f * z, 0.01f * z}, 0.9f,
                          {float(i % 3) / 2.0f, float(i % 5) / 4.0f, float(i % 2)});
  }
  return s;
}

// Span of each chunk in inverse base-camera depth, and the whole binned range.
std::pair<double, double> widest_disparity_span(const scene::GaussianScene& s, const ReferenceCamera& ref,
                                                const DepthChunks& c) {
  double widest = 0, w_min = 1e30, w_max = 0;
  for (const auto& members : c.members) {
    double lo = 1e30, hi = 0;
    for (uint32_t i : members) {
      const auto& p = s.positions[i];
      const double w = 1.0 / (ref.camera.to_camera(glm::vec3(p[0], p[1], p[2])).z + ref.d_forward_eff);
      lo = std::min(lo, w), hi = std::max(hi, w);
    }
    widest = std::max(widest, hi - lo);
    w_min = std::min(w_min, lo), w_max = std::max(w_max, hi);
  }
  return {widest, w_max - w_min};
}

TEST(G2lf, MixedBinningBoundsTheDisparitySpanOfEveryChunk) {
  const scene::GaussianScene s = cluster_before_sparse_background();
  const Fixture& f = fixture();
  const ReferenceCamera ref = make_reference_camera(f.geometry, 0.5f, 1);
  const int n = 16;
  const auto [mixed_span, range] = widest_disparity_span(s, ref, bin_by_depth(s, f.geometry, ref, n, ChunkBinning::kMixed));
  const auto [quantile_span, range_q] = widest_disparity_span(s, ref, bin_by_depth(s, f.geometry, ref, n));
  EXPECT_LE(mixed_span, range / (n / 2) * 1.0001);
  EXPECT_GT(quantile_span, 2.0 * range / (n / 2));  // the background's chunk spans much more
}

TEST(G2lf, MixedBinningKeepsEveryGaussianInAtMostNChunksFrontToBack) {
  const scene::GaussianScene s = cluster_before_sparse_background();
  const Fixture& f = fixture();
  const ReferenceCamera ref = make_reference_camera(f.geometry, 0.5f, 1);
  const DepthChunks q = bin_by_depth(s, f.geometry, ref, 16), m = bin_by_depth(s, f.geometry, ref, 16, ChunkBinning::kMixed);
  size_t total_q = 0, total_m = 0;
  for (const auto& c : q.members) total_q += c.size();
  for (const auto& c : m.members) total_m += c.size();
  EXPECT_EQ(total_m, total_q);
  EXPECT_LE(m.members.size(), 16u);
  for (size_t k = 1; k < m.plane_depth.size(); ++k) EXPECT_GE(m.plane_depth[k], m.plane_depth[k - 1]);
}

TEST(G2lf, MixedBinningRendersASparseBackgroundBetterThanCountQuantiles) {
  const scene::GaussianScene s = cluster_before_sparse_background();
  const Camera base = make_look_at_camera({0, 0, 0}, {0, 0, 3.5f}, {0, 1, 0}, 0.6f, 64, 64);
  const QuiltGeometry g = make_quilt_geometry(base, 3.5f, 40.0f, 9);
  const QuiltLayout layout = make_quilt_layout(g, 9, 1);
  const ImageF truth = render_quilt_per_view(s, g, layout);
  G2lfOptions o;
  o.chunks = 16;
  o.binning = ChunkBinning::kQuantile;
  const double p_quantile = psnr(render_quilt_g2lf(s, g, layout, o), truth);
  o.binning = ChunkBinning::kMixed;
  const double p_mixed = psnr(render_quilt_g2lf(s, g, layout, o), truth);
  std::printf("G2LF 16 chunks on a sparse background: quantile %.2f dB, mixed %.2f dB\n", p_quantile, p_mixed);
  EXPECT_GT(p_mixed, p_quantile + 1.0);
}

}  // namespace
}  // namespace lfd::render
