// V2LF's splitting of voxels that straddle a chunk boundary, its binnings and its plane low-pass
// filter (voxel/voxel_split.hpp, voxel/v2lf.hpp, voxel/plane_lowpass.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <utility>

#include "render/image_metrics.hpp"
#include "tests/support/voxel_tabletop.hpp"
#include "voxel/plane_lowpass.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_quilt.hpp"
#include "voxel/voxel_split.hpp"
#include "voxel_test_scenes.hpp"

namespace lfd::voxel {
namespace {

// The child of `first`..`first + 7` whose box holds `p`.
size_t child_holding(const scene::VoxelScene& s, size_t first, const glm::vec3& p) {
  for (size_t c = first; c < first + 8; ++c) {
    const glm::vec3 lo = s.voxel_min(c), hi = lo + s.voxel_size(c);
    if (glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi))) return c;
  }
  return first + 8;
}

TEST(VoxelSplit, ChildrenKeepTheDensityFieldAtRandomPoints) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> density(-5.0f, 20.0f), unit(0.0f, 1.0f);
  scene::VoxelScene s = testing::empty_scene();
  s.scene_extent = 4.0f;
  testing::add_voxel(s, {5, 2, 7}, 3, 0.0f, {0.2f, 0.4f, 0.6f});
  for (float& d : s.corner_density[0]) d = density(rng);
  // Two levels: the children of the first child too.
  const size_t first = append_children(s, 0, s);
  const size_t grand = append_children(s, first + 6, s);
  ASSERT_EQ(s.size(), 17u);
  for (size_t c = first; c < first + 8; ++c) {
    EXPECT_EQ(s.level[c], 4);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(s.voxel_sh(c)[k], s.voxel_sh(0)[k]);
  }
  for (int n = 0; n < 2000; ++n) {
    const glm::vec3 p = s.voxel_min(0) + s.voxel_size(0) * glm::vec3(unit(rng), unit(rng), unit(rng));
    const float parent = raw_density_at(s, 0, p);
    const size_t child = child_holding(s, first, p);
    ASSERT_LT(child, first + 8u);
    EXPECT_NEAR(raw_density_at(s, child, p), parent, 1e-4f);
    if (child == first + 6) {
      EXPECT_NEAR(raw_density_at(s, child_holding(s, grand, p), p), parent, 1e-4f);
    }
  }
}

TEST(VoxelSplit, ChildrenTileTheParent) {
  scene::VoxelScene s = testing::empty_scene();
  testing::add_voxel(s, {1, 0, 1}, 1, 3.0f, {1, 0, 0});
  const size_t first = append_children(s, 0, s);
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (size_t c = first; c < first + 8; ++c) {
    EXPECT_FLOAT_EQ(s.voxel_size(c), 0.5f * s.voxel_size(0));
    lo = glm::min(lo, s.voxel_min(c));
    hi = glm::max(hi, s.voxel_min(c) + s.voxel_size(c));
  }
  EXPECT_EQ(lo, s.voxel_min(0));
  EXPECT_EQ(hi, s.voxel_min(0) + s.voxel_size(0));
}

using Fixture = test::VoxelTabletop;

// The tabletop of V2lf.ManyChunksApproachThePerViewQuilt; the truth with SVRaster's supersampling
// (ss 1.5), the filter V2LF's low-pass stands in for.
const Fixture& fixture() {
  // K = 8: fine enough that the density field, not the midpoint rule on a coarse voxel, decides
  // the image, so splitting's effect on the chunking shows (with K = 1 children move a sharp
  // surface inside their parent: voxel/v2lf.hpp).
  static const Fixture f = test::make_voxel_tabletop([](scene::VoxelScene& s) { s.samples_per_voxel = 8; });
  return f;
}

V2lfOptions options(int chunks, int split_levels, bool lowpass = true) {
  V2lfOptions o;
  o.planes.chunks = chunks;
  o.planes.precision = render::PlanePrecision::kF32;
  o.planes.filter = render::PlaneFilter::kBilinear;
  o.planes.plane_scale = 2;
  o.planes.binning = render::ChunkBinning::kQuantile;
  o.planes.adaptive_filter = lowpass;
  o.split_levels = split_levels;
  return o;
}

double psnr_of(const V2lfOptions& o, V2lfStats* stats = nullptr) {
  const Fixture& f = fixture();
  return render::psnr(render_quilt_v2lf(f.scene, f.geometry, f.layout, o, f.scene.background, stats), f.truth);
}

TEST(V2lfSplit, SplittingDoesNotLowerThePsnr) {
  for (int chunks : {16, 96}) {
    V2lfStats s0, s1;
    const double none = psnr_of(options(chunks, 0), &s0), one = psnr_of(options(chunks, 1), &s1);
    std::cout << chunks << " chunks: no split " << none << " dB (" << s0.voxels_binned << " voxels), split "
              << one << " dB (" << s1.voxels_split << " split, " << s1.voxels_binned << " binned)\n";
    EXPECT_GT(s1.voxels_split, 0u);
    EXPECT_GE(one, none);
  }
}

TEST(V2lfSplit, EveryVoxelInFrontIsBinnedOnceOrReplacedByItsChildren) {
  const Fixture& f = fixture();
  const render::ReferenceCamera ref = render::make_reference_camera(f.geometry, 0.0f, 1);
  const VoxelChunks plain = bin_voxels_by_depth(f.scene, f.geometry, ref, 64, render::ChunkBinning::kQuantile, 0);
  const VoxelChunks split = bin_voxels_by_depth(f.scene, f.geometry, ref, 64, render::ChunkBinning::kQuantile, 1);
  size_t plain_count = 0, originals = 0, children = 0;
  for (const auto& m : plain.chunks.members) plain_count += m.size();
  for (const auto& m : split.chunks.members)
    for (uint32_t i : m) (i < f.scene.size() ? originals : children) += 1;
  EXPECT_EQ(originals + split.voxels_split, plain_count);
  EXPECT_EQ(children, split.children);
  EXPECT_GT(children, 0u);
  EXPECT_LE(children, 8 * split.voxels_split);
  for (float d : split.chunks.plane_depth)
    EXPECT_NE(std::find(plain.chunks.plane_depth.begin(), plain.chunks.plane_depth.end(), d),
              plain.chunks.plane_depth.end());
  for (const auto& m : split.chunks.members) EXPECT_FALSE(m.empty());
}

TEST(V2lfBinning, MixedBinningCutsOtherChunksThanQuantiles) {
  const Fixture& f = fixture();
  const render::ReferenceCamera ref = render::make_reference_camera(f.geometry, 0.0f, 1);
  const auto q = bin_voxels_by_depth(f.scene, f.geometry, ref, 16, render::ChunkBinning::kQuantile);
  const auto m = bin_voxels_by_depth(f.scene, f.geometry, ref, 16, render::ChunkBinning::kMixed);
  size_t nq = 0, nm = 0;
  for (const auto& c : q.chunks.members) nq += c.size();
  for (const auto& c : m.chunks.members) nm += c.size();
  EXPECT_EQ(nq, nm);
  EXPECT_NE(q.chunks.plane_depth, m.chunks.plane_depth);
  for (size_t k = 1; k < m.chunks.plane_depth.size(); ++k)
    EXPECT_GE(m.chunks.plane_depth[k], m.chunks.plane_depth[k - 1]);
}

TEST(PlaneLowpass, KeepsAUniformImageAndSpreadsAPoint) {
  render::RasterImage img;
  img.width = 9;
  img.height = 7;
  img.rgb.assign(9 * 7 * 3, 0.25f);
  img.transmittance.assign(9 * 7, 0.5f);
  img.rgb[3 * (3 * 9 + 4)] = 1.25f;  // one bright red texel in the middle
  gaussian_lowpass(img, 1.0f);
  for (float t : img.transmittance) EXPECT_NEAR(t, 0.5f, 1e-6f);
  EXPECT_NEAR(img.rgb[1], 0.25f, 1e-6f);
  const float centre = img.rgb[3 * (3 * 9 + 4)], beside = img.rgb[3 * (3 * 9 + 5)];
  EXPECT_LT(centre, 1.25f);
  EXPECT_GT(beside, 0.25f);
  EXPECT_GT(centre, beside);
}

// The filter works only on the box around the non-empty texels; the result must be the
// whole-plane filter's: a direct 2D sum with clamped edges.
TEST(PlaneLowpass, MatchesTheWholePlaneFilterOnASparsePlane) {
  render::RasterImage img;
  img.width = 40;
  img.height = 30;
  img.rgb.assign(40 * 30 * 3, 0.0f);
  img.transmittance.assign(40 * 30, 1.0f);
  for (auto [x, y] : {std::pair{12, 9}, std::pair{14, 11}, std::pair{39, 10}}) {
    img.rgb[3 * (y * 40 + x) + 1] = 0.7f;
    img.transmittance[y * 40 + x] = 0.2f;
  }
  const render::RasterImage in = img;
  const float variance = 1.7f;
  gaussian_lowpass(img, variance);
  const int r = int(std::ceil(3.0f * std::sqrt(variance)));
  double norm = 0.0;
  for (int k = -r; k <= r; ++k) norm += std::exp(-0.5 * k * k / variance);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      double g = 0.0, t = 0.0;
      for (int j = -r; j <= r; ++j)
        for (int i = -r; i <= r; ++i) {
          const size_t q = size_t(std::clamp(y + j, 0, 29) * 40 + std::clamp(x + i, 0, 39));
          const double w = std::exp(-0.5 * (i * i + j * j) / variance) / (norm * norm);
          g += w * in.rgb[3 * q + 1];
          t += w * in.transmittance[q];
        }
      ASSERT_NEAR(img.rgb[3 * (y * 40 + x) + 1], g, 1e-5) << x << "," << y;
      ASSERT_NEAR(img.transmittance[size_t(y * 40 + x)], t, 1e-5) << x << "," << y;
    }
}

TEST(PlaneLowpass, BringsV2lfCloserToTheSupersampledQuilt) {
  const double with = psnr_of(options(128, 0, true)), without = psnr_of(options(128, 0, false));
  std::cout << "128 chunks vs ss 1.5 per-view: low-pass " << with << " dB, none " << without << " dB\n";
  EXPECT_GT(with, without);
}

}  // namespace
}  // namespace lfd::voxel
