// render::PlaneRays (docs/performance.md "Where the direct pass's time went"): the row kernel
// (offset bins, blended plane rows, windows of rays per non-empty run, vectorised sampling)
// against composite_ray, the swizzle's sampling and blend spelled out for one ray, on planes of
// sparse random blobs (many runs per row, empty gaps, both precisions, both filters) and on the
// flat layers of the direct-panel tests.
#include "render/plane_rays.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/camera.hpp"
#include "tests/interlace/flat_layer_planes.hpp"

namespace lfd::render {
namespace {

struct Planes {
  QuiltGeometry geometry;
  ReferenceCamera ref;
  SweepingPlanes planes;
};

// `count` planes of small random blobs of random colour and transmittance: sparse rows with many
// runs and gaps, some planes nearly empty, some rays stopped early by dense blobs.
Planes random_blob_planes(int count, PlanePrecision precision, unsigned seed) {
  Planes p;
  const Camera base = make_look_at_camera(glm::vec3(0, 0, 0), glm::vec3(0, 0, 2), glm::vec3(0, -1, 0), 0.8f, 96, 64);
  p.geometry = make_quilt_geometry(base, 2.0f, 50.0f, 16);
  p.ref = make_reference_camera(p.geometry, forward_distance(p.geometry), 1);
  std::vector<float> depths;
  for (int k = 0; k < count; ++k) depths.push_back(1.0f + 3.0f * float(k) / float(count));
  const int w = p.ref.camera.width, h = p.ref.camera.height;
  p.planes = make_sweeping_planes(p.ref, depths, precision, [&](int k) {
    std::mt19937 rng(seed + unsigned(k));
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    RasterImage image;
    image.width = w;
    image.height = h;
    image.rgb.assign(size_t(w) * h * 3, 0.0f);
    image.transmittance.assign(size_t(w) * h, 1.0f);
    const int blobs = int(unit(rng) * 40.0f);
    for (int b = 0; b < blobs; ++b) {
      const int cx = int(unit(rng) * w), cy = int(unit(rng) * h), rx = 1 + int(unit(rng) * 4), ry = 1 + int(unit(rng) * 6);
      const float t = unit(rng) < 0.2f ? 0.0f : unit(rng);
      const glm::vec3 colour(unit(rng), unit(rng), unit(rng));
      for (int y = std::max(0, cy - ry); y < std::min(h, cy + ry); ++y)
        for (int x = std::max(0, cx - rx); x < std::min(w, cx + rx); ++x) {
          const size_t i = size_t(y) * w + x;
          image.transmittance[i] = t;
          for (int c = 0; c < 3; ++c) image.rgb[i * 3 + size_t(c)] = (1.0f - t) * colour[c];
        }
    }
    return image;
  });
  return p;
}

// A row of rays as the direct pass makes them: three per pixel in order of u, each at an offset
// anywhere in the cone.
std::vector<PlaneRay> random_row(const QuiltGeometry& g, int pixels, std::mt19937& rng) {
  std::uniform_real_distribution<float> position(-0.5f, 0.5f);
  std::vector<PlaneRay> rays;
  for (int x = 0; x < pixels; ++x)
    for (int c = 0; c < 3; ++c)
      rays.push_back({g.view_offset_at(position(rng)), (2.0f * float(x) + 1.0f) / float(pixels) - 1.0f, c});
  return rays;
}

struct Agreement {
  size_t rays = 0, off = 0;  // rays, and those off by more than 1e-5
  double max_difference = 0;
};

Agreement compare(const Planes& p, PlaneFilter filter, unsigned seed) {
  const glm::vec3 background(0.1f, 0.2f, 0.3f);
  const PlaneRays rays(p.planes, p.geometry, p.ref, filter, background);
  const float max_abs_dx = std::abs(p.geometry.view_offset_at(0.5f));
  std::mt19937 rng(seed);
  PlaneRays::Scratch scratch;
  std::vector<float> out;
  Agreement a;
  for (int y = 0; y < p.geometry.base.height; y += 3) {
    const float v_ndc = (2.0f * float(y) + 1.0f) / float(p.geometry.base.height) - 1.0f;
    const std::vector<PlaneRay> row = random_row(p.geometry, 2 * p.geometry.base.width, rng);
    rays.composite_row(v_ndc, max_abs_dx, row, out, scratch);  // the scratch reused across rows
    EXPECT_EQ(out.size(), row.size());
    for (size_t i = 0; i < row.size(); ++i) {
      const double d = std::abs(double(out[i]) - rays.composite_ray(row[i], v_ndc));
      ++a.rays;
      if (d > 1e-5) ++a.off;
      a.max_difference = std::max(a.max_difference, d);
    }
  }
  return a;
}

TEST(PlaneRays, RowKernelEqualsTheOneRayDefinitionOnSparseBlobs) {
  for (PlanePrecision precision : {PlanePrecision::kU8, PlanePrecision::kF32})
    for (PlaneFilter filter : {PlaneFilter::kBilinear, PlaneFilter::kNearest}) {
      const Planes p = random_blob_planes(48, precision, 7);
      const Agreement a = compare(p, filter, 11);
      const std::string what = std::string(precision == PlanePrecision::kU8 ? "u8 " : "f32 ") +
                               (filter == PlaneFilter::kBilinear ? "bilinear" : "nearest");
      EXPECT_GT(a.rays, 5000u) << what;
      // Summation order differs (the vertical blend first); a ray whose transmittance lands within
      // rounding of the stopping threshold may take one plane more or less, which moves it by at
      // most that threshold (half an 8-bit step).
      EXPECT_LE(double(a.off), 1e-3 * double(a.rays)) << what;
      EXPECT_LT(a.max_difference, 0.5 / 255 + 1e-5) << what;
    }
}

TEST(PlaneRays, RowKernelEqualsTheOneRayDefinitionOnFlatLayers) {
  const test_planes::FlatLayerScene s = test_planes::flat_layer_scene(120, 80, 9, PlanePrecision::kU8);
  const Planes p{s.geometry, s.ref, s.planes};
  const Agreement a = compare(p, PlaneFilter::kBilinear, 3);
  EXPECT_GT(a.rays, 5000u);
  EXPECT_EQ(a.off, 0u);
  EXPECT_LT(a.max_difference, 1e-5);
}

TEST(PlaneRays, RaysOutsideEveryPlaneShowTheBackground) {
  const Planes p = random_blob_planes(8, PlanePrecision::kF32, 1);
  const PlaneRays rays(p.planes, p.geometry, p.ref, PlaneFilter::kBilinear, glm::vec3(0.25f, 0.5f, 0.75f));
  // Far outside the view horizontally: no plane reaches there.
  const std::vector<PlaneRay> row{{0.0f, -40.0f, 0}, {0.0f, 40.0f, 1}, {0.0f, 60.0f, 2}};
  std::vector<float> out;
  rays.composite_row(0.0f, std::abs(p.geometry.view_offset_at(0.5f)), row, out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_FLOAT_EQ(out[0], 0.25f);
  EXPECT_FLOAT_EQ(out[1], 0.5f);
  EXPECT_FLOAT_EQ(out[2], 0.75f);
}

}  // namespace
}  // namespace lfd::render
