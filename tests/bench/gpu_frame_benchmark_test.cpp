// lfd bench gpu-frame's loop (bench/gpu_frame_benchmark.hpp) on llvmpipe: one row per variant,
// each timed and with the stage times of its method.
#include <gtest/gtest.h>

#include "bench/gpu_frame_benchmark.hpp"
#include "gpu/gl/gl_context.hpp"

namespace lfd::bench {
namespace {

// A short run of `rasters` on 5 views, N_chunk 8, no V2LF rows (their own test).
GpuFrameOptions short_run(gpu::RasterPath raster) {
  GpuFrameOptions o;
  o.views = 5;
  o.chunks = 8;
  o.runs = 2;
  o.warmup = 1;
  o.batch = 2;
  o.voxel_level = 0;
  o.rasters = {raster};
  return o;
}

TEST(GpuFrameBenchmark, TimesEveryVariantWithItsStages) {
  gpu::HeadlessContext context;
  const GlVsCpuScene scene = gl_vs_cpu_tabletop(2000, 32);
  GpuFrameOptions o = short_run(gpu::RasterPath::kHardware);  // the compute rows: their own test
  o.swizzle_views = {1, 3};
  const std::vector<GpuFrameRow> rows = run_gpu_frame(scene, o, context.info());
  // G2LF: 2 swizzle variants, 3 plane rasters, table off/on, bilinear by hand/unit, timers read
  // late; per view: 4.
  ASSERT_EQ(rows.size(), 14u);
  for (const GpuFrameRow& r : rows) {
    EXPECT_GT(r.frame_s, 0.0) << r.method << ", " << r.variant;
    EXPECT_EQ(r.runs, 2);
  }
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(rows[size_t(i)].method, "G2LF N=8");
    EXPECT_GT(rows[size_t(i)].swizzle_s, 0.0);
    EXPECT_EQ(rows[size_t(i)].raster_s, 0.0);
  }
  for (int i = 10; i < 14; ++i) {
    EXPECT_EQ(rows[size_t(i)].method, "per view");
    EXPECT_GT(rows[size_t(i)].raster_s, 0.0);
  }
  const std::string table = gpu_frame_table(rows);
  EXPECT_NE(table.find("swizzle 3 views/invocation"), std::string::npos);
  // Each plane raster row names the planes as drawn.
  EXPECT_NE(table.find("--planes batched; planes batched u8"), std::string::npos) << table;
  EXPECT_NE(table.find("--planes layered; planes layered f16"), std::string::npos) << table;
  EXPECT_NE(table.find("--planes layered-rgba8; planes layered u8"), std::string::npos) << table;
  EXPECT_NE(table.find("bilinear by the texture unit"), std::string::npos) << table;
  EXPECT_EQ(gpu_frame_json(rows).size(), 14u);
  o.per_view = false;
  o.planes = {"layered"};
  o.swizzle_table = {true};
  o.hardware_bilinear = {true};
  o.swizzle_views = {8};
  EXPECT_EQ(run_gpu_frame(scene, o, context.info()).size(), 5u) << "G2LF rows only";
}

// --raster compute: G2LF's planes (timers waited for and read late) and the per-view quilt drawn
// by the compute tile rasterizer, each with its GPU stage times; with hardware, after its rows.
TEST(GpuFrameBenchmark, ComputeRowsHaveTheirStageTimes) {
  gpu::HeadlessContext context;
  const GlVsCpuScene scene = gl_vs_cpu_tabletop(2000, 32);
  GpuFrameOptions o = short_run(gpu::RasterPath::kCompute);
  const std::vector<GpuFrameRow> rows = run_gpu_frame(scene, o, context.info());
  ASSERT_EQ(rows.size(), 3u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(rows[i].method, "G2LF N=8");
    EXPECT_NE(rows[i].variant.find("--raster compute"), std::string::npos) << rows[i].variant;
    EXPECT_NE(rows[i].variant.find("planes compute"), std::string::npos) << rows[i].variant;
    EXPECT_GT(rows[i].planes_s, 0.0) << rows[i].variant;
    EXPECT_GT(rows[i].swizzle_s, 0.0) << rows[i].variant;
  }
  EXPECT_EQ(rows[2].method, "per view");
  EXPECT_NE(rows[2].variant.find("--raster compute"), std::string::npos);
  EXPECT_GT(rows[2].raster_s, 0.0);
  EXPECT_GT(rows[2].sort_s, 0.0);
  EXPECT_LT(rows[2].sort_s, rows[2].raster_s);  // the sort is a share of the whole
  o.per_view = false;
  o.rasters = {gpu::RasterPath::kHardware, gpu::RasterPath::kCompute};
  o.planes = {"layered"};
  o.swizzle_table = {true};
  o.hardware_bilinear = {true};
  o.swizzle_views = {8};
  const std::vector<GpuFrameRow> both = run_gpu_frame(scene, o, context.info());
  ASSERT_EQ(both.size(), 7u) << "5 hardware G2LF rows, then 2 compute";
  EXPECT_NE(both[5].variant.find("--raster compute"), std::string::npos);
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
  o.planes = {"layered"};
  o.swizzle_table = {true};
  o.hardware_bilinear = {true};
  o.voxel_level = 4;
  o.rasters = {gpu::RasterPath::kHardware};
  const std::vector<GpuFrameRow> rows = run_gpu_frame(scene, o, context.info());
  // G2LF 5 (swizzle 1, planes layered, table on, unit bilinear, timers read late), per view 4, V2LF 2
  ASSERT_EQ(rows.size(), 11u);
  for (size_t i = 9; i < 11; ++i) {
    EXPECT_EQ(rows[i].method, "V2LF N=8");
    EXPECT_EQ(rows[i].runs, 2);
    EXPECT_GT(rows[i].frame_s, 0.0);
    EXPECT_GT(rows[i].planes_s, 0.0);
    EXPECT_GT(rows[i].swizzle_s, 0.0);
  }
  EXPECT_NE(rows[9].variant.find("binning on the CPU"), std::string::npos);
  EXPECT_NE(rows[10].variant.find("binning on the GPU"), std::string::npos);
}

}  // namespace
}  // namespace lfd::bench
