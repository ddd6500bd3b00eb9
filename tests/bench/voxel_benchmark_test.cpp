// lfd bench voxels on a tiny generated scene: the table's shape and that its figures are those
// of V2LF against the per-view quilt.
#include <gtest/gtest.h>

#include "bench/bench_renderers.hpp"
#include "bench/voxel_benchmark.hpp"
#include "util/error.hpp"

namespace lfd::bench {
namespace {

VoxelBenchOptions tiny() {
  VoxelBenchOptions o;
  o.generated_level = 5;
  o.views = {3};
  o.size = 32;
  o.only_chunks = 64;
  o.runs = 1;
  o.warmup = 0;
  return o;
}

TEST(VoxelBenchmark, TimesPerViewAndTheTable1RowsOfOneChunkCount) {
  const BenchRenderers cpu = make_bench_renderers("cpu", scene::SceneKind::kVoxels);
  const nlohmann::ordered_json r = run_voxel_benchmark(*cpu.per_view, *cpu.sweeping, tiny());
  ASSERT_EQ(r["tables"].size(), 1u);
  const auto& rows = r["tables"][0]["rows"];
  ASSERT_EQ(rows.size(), 3u);  // per view, V2LF (N=64), V2LF (N=64, Ps=2)
  EXPECT_TRUE(rows[0]["psnr_db"].is_null());
  EXPECT_EQ(rows[1]["method"], "V2LF (N=64)");
  EXPECT_EQ(rows[2]["plane_scale"], 2);
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(rows[i]["psnr_db"].get<double>(), 15.0);
    EXPECT_LE(rows[i]["ssim"].get<double>(), 1.0);
    EXPECT_GT(rows[i]["plane_bytes"].get<size_t>(), 0u);
    EXPECT_GT(rows[i]["planes"].get<int>(), 1);
  }
}

// The same table on the GL voxel path (llvmpipe here): both sides on the GPU, GPU memory.
TEST(VoxelBenchmark, TheGlBackendTimesTheSameRows) {
  const BenchRenderers gl = make_bench_renderers("gl", scene::SceneKind::kVoxels);
  const nlohmann::ordered_json r = run_voxel_benchmark(*gl.per_view, *gl.sweeping, tiny());
  EXPECT_EQ(r["backend"], "gl");
  const auto& rows = r["tables"][0]["rows"];
  ASSERT_EQ(rows.size(), 3u);
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(rows[i]["psnr_db"].get<double>(), 15.0);
    EXPECT_GT(rows[i]["peak_bytes"].get<size_t>(), rows[i]["plane_bytes"].get<size_t>() / 2);
  }
}

TEST(VoxelBenchmark, RefusesAnUnknownConfigurationSet) {
  VoxelBenchOptions o = tiny();
  o.config_sets = {"table9"};
  const BenchRenderers cpu = make_bench_renderers("cpu", scene::SceneKind::kVoxels);
  EXPECT_THROW(run_voxel_benchmark(*cpu.per_view, *cpu.sweeping, o), InputError);
}

}  // namespace
}  // namespace lfd::bench
