// lfd bench gpu-frame's loop (bench/gpu_frame_benchmark.hpp) on llvmpipe: one row per variant,
// each timed and with the stage times of its method.
#include <gtest/gtest.h>

#include "bench/gpu_frame_benchmark.hpp"
#include "gpu/gl_context.hpp"

namespace lfd::bench {
namespace {

TEST(GpuFrameBenchmark, TimesEveryVariantWithItsStages) {
  gpu::HeadlessContext context;
  const GlVsCpuScene scene = gl_vs_cpu_tabletop(2000, 32);
  GpuFrameOptions o;
  o.views = 5;
  o.chunks = 8;
  o.runs = 2;
  o.warmup = 1;
  o.batch = 2;
  o.swizzle_views = {1, 3};
  o.voxel_level = 0;  // no V2LF rows: the next test's
  const std::vector<GpuFrameRow> rows = run_gpu_frame(scene, o, context.info());
  ASSERT_EQ(rows.size(), 7u);  // G2LF: 2 swizzle variants + timers read late; per view: 4
  for (const GpuFrameRow& r : rows) {
    EXPECT_GT(r.frame_s, 0.0) << r.method << ", " << r.variant;
    EXPECT_EQ(r.runs, 2);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(rows[size_t(i)].method, "G2LF N=8");
    EXPECT_GT(rows[size_t(i)].swizzle_s, 0.0);
    EXPECT_EQ(rows[size_t(i)].raster_s, 0.0);
  }
  for (int i = 3; i < 7; ++i) {
    EXPECT_EQ(rows[size_t(i)].method, "per view");
    EXPECT_GT(rows[size_t(i)].raster_s, 0.0);
  }
  EXPECT_NE(gpu_frame_table(rows).find("swizzle 3 views/invocation"), std::string::npos);
  EXPECT_EQ(gpu_frame_json(rows).size(), 7u);
}

// --sort-only: G2LF's binning sort over all N and over the binned Gaussians, then per view five
// sorts (all N / the visible, float / normalised keys), each with its stage time.
TEST(GpuFrameBenchmark, TheSortRowsCompareTheSortsInterleaved) {
  gpu::HeadlessContext context;
  const GlVsCpuScene scene = gl_vs_cpu_tabletop(2000, 32);
  GpuFrameOptions o;
  o.views = 3;
  o.chunks = 8;
  o.runs = 2;
  o.warmup = 1;
  o.sort_only = true;
  const std::vector<GpuFrameRow> rows = run_gpu_frame(scene, o, context.info());
  ASSERT_EQ(rows.size(), 7u);
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].method, i < 2 ? "G2LF N=8" : "per view");
    EXPECT_GT(rows[i].frame_s, 0.0) << rows[i].variant;
    EXPECT_GT(i < 2 ? rows[i].binning_s : rows[i].sort_s, 0.0) << rows[i].variant;
    EXPECT_NE(rows[i].variant.find("interleaved"), std::string::npos);
  }
  EXPECT_NE(rows[4].variant.find("16-bit normalised"), std::string::npos);
  EXPECT_NE(gpu_frame_table(rows).find("GPU per-view sort ms"), std::string::npos);
}

// The V2LF rows: the same frames binned on the CPU (uploaded) and on the GPU, each with its
// stages, after the G2LF and per-view rows.
TEST(GpuFrameBenchmark, ComparesV2lfBinnedOnTheCpuAndOnTheGpu) {
  gpu::HeadlessContext context;
  const GlVsCpuScene scene = gl_vs_cpu_tabletop(2000, 32);
  GpuFrameOptions o;
  o.views = 5;
  o.chunks = 8;
  o.runs = 2;
  o.warmup = 1;
  o.batch = 2;
  o.swizzle_views = {1};
  o.voxel_level = 4;
  const std::vector<GpuFrameRow> rows = run_gpu_frame(scene, o, context.info());
  ASSERT_EQ(rows.size(), 8u);  // G2LF 2, per view 4, V2LF 2
  for (size_t i = 6; i < 8; ++i) {
    EXPECT_EQ(rows[i].method, "V2LF N=8");
    EXPECT_EQ(rows[i].runs, 2);
    EXPECT_GT(rows[i].frame_s, 0.0);
    EXPECT_GT(rows[i].planes_s, 0.0);
    EXPECT_GT(rows[i].swizzle_s, 0.0);
  }
  EXPECT_NE(rows[6].variant.find("binning on the CPU"), std::string::npos);
  EXPECT_NE(rows[7].variant.find("binning on the GPU"), std::string::npos);
}

}  // namespace
}  // namespace lfd::bench
