// lfd bench render's machinery (bench/): robust timing statistics, planes at view density, and
// the benchmark loop driven through a fake backend (what is timed, how often, what is compared).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bench/render_benchmark.hpp"
#include "bench/render_configs.hpp"
#include "bench/timing_stats.hpp"
#include "lightfield/light_field_renderer.hpp"
#include "render/camera_json.hpp"
#include "render/quilt_geometry.hpp"
#include "util/error.hpp"

namespace lfd::bench {
namespace {

TEST(TimingStats, MedianMinMaxAndMedianAbsoluteDeviation) {
  const TimingStats odd = summarize({3.0, 1.0, 10.0, 2.0, 2.5});
  EXPECT_DOUBLE_EQ(odd.median, 2.5);
  EXPECT_DOUBLE_EQ(odd.min, 1.0);
  EXPECT_DOUBLE_EQ(odd.max, 10.0);
  EXPECT_DOUBLE_EQ(odd.mad, 0.5);  // deviations 0.5, 1.5, 7.5, 0.5, 0
  EXPECT_EQ(odd.samples.size(), 5u);
  const TimingStats even = summarize({4.0, 1.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(even.median, 2.5);
  EXPECT_DOUBLE_EQ(even.mad, 1.0);
  EXPECT_DOUBLE_EQ(summarize({}).median, 0.0);
}

render::QuiltGeometry square_geometry(int size, int views) {
  render::CameraSpec spec;
  spec.position = glm::vec3(0.0f, 0.0f, -5.0f);
  spec.look_at = glm::vec3(0.0f);
  spec.up = glm::vec3(0.0f, -1.0f, 0.0f);
  spec.fov_y_deg = 40.0f;
  return render::make_quilt_geometry(render::camera_from_spec(spec, size, size), 5.0f, 40.0f, views);
}

// View pixel over plane texel on the focal plane (>= 1: the plane is at least as fine).
float density_ratio(const render::QuiltGeometry& g, float d_shift, int plane_scale) {
  const render::ReferenceCamera ref = render::make_reference_camera(g, d_shift, plane_scale);
  return std::sqrt(render::adaptive_filter_variance(g, ref, plane_scale, 1.0f));
}

TEST(EqualDensity, IsTheSmallestPlaneScaleWhoseTexelIsNoLargerThanAViewPixel) {
  const render::QuiltGeometry g = square_geometry(256, 45);
  const float d_forward = render::make_reference_camera(g, 0.0f, 1).d_forward;
  for (float d_shift : {0.0f, 0.5f * d_forward, d_forward}) {
    const int ps = equal_density_plane_scale(g, d_shift);
    EXPECT_GE(density_ratio(g, d_shift, ps), 1.0f - 1e-4f) << d_shift;
    if (ps > 1) {
      EXPECT_LT(density_ratio(g, d_shift, ps - 1), 1.0f) << d_shift;
    }
  }
  // With the reference camera at the base camera (D_shift = D_forward), P_s = 1 is coarser.
  EXPECT_GT(equal_density_plane_scale(g, d_forward), 1);
}

TEST(RenderConfigs, Table1IsThePapersSevenRowsAndUnknownSetsAreRefused) {
  const auto table1 = g2lf_configs_in({"table1"}, "configs");
  ASSERT_EQ(table1.size(), 7u);
  EXPECT_EQ(table1.front().chunks, 64);
  EXPECT_EQ(table1.back().chunks, 512);
  EXPECT_EQ(table1.back().plane_scale, 3);
  EXPECT_EQ(table1.back().filter, render::PlaneFilter::kBilinear);
  EXPECT_THROW(g2lf_configs_in({"table2"}, "configs"), InputError);
}

// What the fake backend's two renderers count together.
struct FakeCounts {
  size_t scene_size = 0;
  int per_view_frames = 0, g2lf_frames = 0, reads = 0, resets = 0, last_plane_scale = 0;
};

// A backend whose frames cost nothing: per-view quilts are 0.5 grey, G2LF ones 0.51 (PSNR
// 40 dB against them); it counts its calls and whether quilts are read inside a frame.
class FakeRenderer final : public lightfield::LightFieldRenderer {
 public:
  FakeRenderer(lightfield::Method method, FakeCounts& counts) : counts_(counts) { options_.method = method; }
  std::string name() const override { return "fake"; }
  std::string device() const override { return "none"; }
  int default_runs() const override { return 4; }
  const lightfield::RendererOptions& options() const override { return options_; }
  void set_options(const lightfield::RendererOptions& options) override { options_ = options; }
  void set_scene(const scene::Scene& scene) override { counts_.scene_size = scene.size(); }
  lightfield::QuiltStats render_quilt(const render::QuiltGeometry&, const render::QuiltLayout& layout) override {
    if (options_.method == lightfield::Method::kPerView) {
      ++counts_.per_view_frames;
      quilt_ = ImageF(layout.width, layout.height, 3, 0.5f);
      return {};
    }
    ++counts_.g2lf_frames;
    counts_.last_plane_scale = options_.planes.plane_scale;
    quilt_ = ImageF(layout.width, layout.height, 3, 0.51f);
    return {.planes = options_.planes.chunks, .plane_bytes = 1000};
  }
  ImageF render_view(const render::QuiltGeometry&, int) override { return {}; }
  const ImageF& read_quilt() override {
    ++counts_.reads;
    return quilt_;
  }
  std::string memory_kind() const override { return "nothing"; }
  void reset_peak_memory() override { ++counts_.resets; }
  size_t peak_memory_bytes() const override { return 123; }

 private:
  FakeCounts& counts_;
  lightfield::RendererOptions options_;
  ImageF quilt_;
};

// The fake backend: a per-view and a G2LF renderer.
struct FakeBackend {
  FakeCounts counts;
  FakeRenderer per_view{lightfield::Method::kPerView, counts};
  FakeRenderer g2lf{lightfield::Method::kSweepingPlanes, counts};
  nlohmann::ordered_json run(const RenderBenchOptions& o) { return run_render_benchmark(per_view, g2lf, o); }
};

TEST(RenderBenchmark, TimesWarmUpPlusRunsPerRowAndComparesWithThePerViewQuilt) {
  RenderBenchOptions o;
  o.scenes = {{"", 500}};
  o.views = {4};
  o.size = {32, 32};
  o.config_sets = {"table1", "density"};
  o.only_chunks = {64};  // N=64, N=64 Ps=2, N=64 at view density
  o.warmup = 1;
  o.runs = 3;
  o.png_runs = 2;
  FakeBackend backend;
  const nlohmann::ordered_json result = backend.run(o);
  const FakeCounts& fake = backend.counts;

  EXPECT_EQ(fake.scene_size, 500u);
  EXPECT_EQ(fake.per_view_frames, 1 + 3);
  EXPECT_EQ(fake.g2lf_frames, 3 * (1 + 3));
  EXPECT_EQ(fake.resets, 4);  // one per row
  // Reads: 2 PNG frames per row, plus the per-view truth and each G2LF row's comparison.
  EXPECT_EQ(fake.reads, 4 * 2 + 1 + 3);
  ASSERT_EQ(result["tables"].size(), 1u);
  const auto& rows = result["tables"][0]["rows"];
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0]["method"], "per-view 3DGS (ground truth)");
  for (const auto& row : rows) {
    EXPECT_EQ(row["seconds"]["samples"].size(), 3u);
    EXPECT_EQ(row["seconds_with_png"]["samples"].size(), 2u);
    EXPECT_EQ(row["peak_bytes"], 123u);
  }
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_NEAR(rows[i]["psnr_db"].get<double>(), 40.0, 1e-3);
    EXPECT_EQ(rows[i]["plane_bytes"], 1000u);
    EXPECT_TRUE(rows[i]["speedup"].is_number());
  }
  EXPECT_EQ(rows[3]["plane_scale"], fake.last_plane_scale);
  EXPECT_GE(fake.last_plane_scale, 1);
}

// The paper's views are not square (45 views of 512x910): the table renders views of W x H, and
// --chunks keeps several N_chunk, --plane-scale one P_s (the GPU table's N=64/256/512 rows).
TEST(RenderBenchmark, NonSquareViewsAndAListOfChunkCounts) {
  RenderBenchOptions o;
  o.scenes = {{"", 300}};
  o.views = {3};
  o.size = {32, 56};
  o.config_sets = {"table1", "chunks"};
  o.only_chunks = {64, 256, 512};
  o.only_plane_scale = 1;
  o.runs = 1;
  o.png_runs = 0;
  FakeBackend backend;
  const nlohmann::ordered_json result = backend.run(o);
  EXPECT_EQ(result["size"], nlohmann::ordered_json::array({32, 56}));
  const auto& table = result["tables"][0];
  const int cols = table["grid"][0], rows = table["grid"][1];
  EXPECT_EQ(table["quilt"][0].get<int>(), 32 * cols);
  EXPECT_EQ(table["quilt"][1].get<int>(), 56 * rows);
  std::vector<std::string> methods;
  for (const auto& row : table["rows"]) methods.push_back(row["method"]);
  // Per view, then Table 1's P_s = 1 rows of N 64 and 512 (nearest, bilinear), then N = 256.
  EXPECT_EQ(methods, (std::vector<std::string>{"per-view 3DGS (ground truth)", "G2LF (N=64)", "G2LF (N=512)",
                                               "G2LF (N=512, Bi.)", "G2LF (N=256)"}));
  o.size = {32, 8};
  EXPECT_THROW(backend.run(o), InputError);
}

TEST(RenderBenchmark, BadOptionsNameTheField) {
  RenderBenchOptions o;
  o.scenes = {{"", 100}};
  FakeBackend backend;
  const FakeCounts& fake = backend.counts;
  o.views = {0};
  try {
    backend.run(o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("views"), std::string::npos) << e.what();
  }
  o.views = {45};
  o.scenes.clear();
  EXPECT_THROW(backend.run(o), InputError);
  o.scenes = {{"", 100}};
  o.binnings = {"median"};
  EXPECT_THROW(backend.run(o), InputError);
  EXPECT_EQ(fake.per_view_frames + fake.g2lf_frames, 0);
}

}  // namespace
}  // namespace lfd::bench
