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

}  // namespace
}  // namespace lfd::bench
