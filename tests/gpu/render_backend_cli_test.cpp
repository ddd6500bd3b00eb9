// `lfd render --backend gl` through the real program: the GL quilt is the CPU's (PSNR >= 40 dB)
// for each plane storage, including f16 (RGBA16F planes), which exists only on the GPU; asking
// the CPU for f16 is one line and exit 2, with nothing written. Voxel scenes likewise, with
// --raster compute and hardware too. The direct
// panel on the GPU (its compute pass over panel tiles) is the CPU's, G2LF and V2LF.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "render/image_metrics.hpp"
#include "tests/apps/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

class RenderBackendCli : public testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("render_backend"); }
  void TearDown() override { fs::remove_all(dir_); }

  // A small G2LF quilt of the bundled demo scene; returns the program's result.
  test::RunResult render(const std::string& out, const std::string& extra) const {
    return test::run_lfd("render --scene '" + (test::project_data() / "scenes" / "demo.ply").string() +
                         "' --views 6 --cols 3 --rows 2 --size 48x32 --chunks 16 --out '" +
                         (dir_ / out).string() + "' " + extra);
  }
  ImageF quilt(const std::string& name) const { return to_float(read_image(dir_ / name, 3)); }

  fs::path dir_;
};

TEST_F(RenderBackendCli, EveryPlaneStorageOnTheGpuMatchesTheCpu) {
  ASSERT_EQ(render("cpu.png", "--backend cpu --precision f32").exit_code, 0);
  for (const std::string precision : {"u8", "f16", "f32"}) {
    SCOPED_TRACE(precision);
    const auto r = render("gl_" + precision + ".png", "--backend gl --precision " + precision);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("on the GPU"), std::string::npos) << r.output;
    EXPECT_GE(render::psnr(quilt("gl_" + precision + "_qs3x2a1.5.png"), quilt("cpu_qs3x2a1.5.png")), 40.0);
  }
}

TEST_F(RenderBackendCli, F16OnTheCpuIsOneLineAndExit2) {
  const auto r = render("cpu16.png", "--backend cpu --precision f16");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  std::istringstream lines(r.output);
  std::string first, second;
  std::getline(lines, first);
  EXPECT_FALSE(std::getline(lines, second)) << r.output;
  EXPECT_NE(first.find("--precision"), std::string::npos) << first;
  EXPECT_FALSE(fs::exists(dir_ / "cpu16_qs3x2a1.5.png"));
}

// --raster: the compute tile rasterizer and the hardware raster give the same quilt of the
// bundled demo scene, per view (12 views of 64x48) and through
// G2LF, from the command line; both equal the CPU's; auto says what it measured and chose; the
// CPU backend has no raster paths (one line, exit 2).
TEST_F(RenderBackendCli, ComputeAndHardwareRasterGiveTheSameQuilt) {
  const std::string scene = (test::project_data() / "scenes" / "demo.ply").string();
  for (const std::string method : {"per-view", "g2lf"}) {
    SCOPED_TRACE(method);
    const std::string common = "render --scene '" + scene + "' --method " + method +
                               " --views 12 --cols 4 --rows 3 --size 64x48 --chunks 32 --precision f32 --out '";
    const auto name = [&](const std::string& path) { return method + "_" + path + ".png"; };
    const auto cpu = test::run_lfd(common + (dir_ / name("cpu")).string() + "' --backend cpu");
    ASSERT_EQ(cpu.exit_code, 0) << cpu.output;
    for (const std::string path : {"hardware", "compute", "auto"}) {
      const auto r = test::run_lfd(common + (dir_ / name(path)).string() + "' --backend gl --raster " + path);
      ASSERT_EQ(r.exit_code, 0) << r.output;
      if (path == "auto") EXPECT_NE(r.output.find("raster: auto chose "), std::string::npos) << r.output;
    }
    const auto q = [&](const std::string& path) { return quilt(method + "_" + path + "_qs4x3a1.3333.png"); };
    EXPECT_GE(render::psnr(q("compute"), q("hardware")), 40.0);
    EXPECT_GE(render::psnr(q("compute"), q("cpu")), 40.0);
    EXPECT_GE(render::psnr(q("auto"), q("cpu")), 40.0);
  }
  const auto r = render("cpu_raster.png", "--backend cpu --raster compute");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--raster"), std::string::npos) << r.output;
}

// A generated voxel scene through the real program: per-view and V2LF quilts on the GPU are the
// CPU's (the GL voxel path, docs/gpu.md "Voxels on the GPU").
TEST_F(RenderBackendCli, VoxelQuiltsOnTheGpuMatchTheCpu) {
  const std::string scene = (dir_ / "scene.voxels").string();
  ASSERT_EQ(test::run_lfd("scene generate --kind voxels --level 5 --out '" + scene + "'").exit_code, 0);
  for (const std::string method : {"per-view", "v2lf"}) {
    SCOPED_TRACE(method);
    const std::string common = "render --scene '" + scene + "' --method " + method +
                               " --views 4 --cols 2 --rows 2 --size 48x32 --chunks 16 --precision f32 --out '";
    const auto cpu = test::run_lfd(common + (dir_ / (method + "_cpu.png")).string() + "' --backend cpu");
    ASSERT_EQ(cpu.exit_code, 0) << cpu.output;
    const auto gl = test::run_lfd(common + (dir_ / (method + "_gl.png")).string() + "' --backend gl");
    ASSERT_EQ(gl.exit_code, 0) << gl.output;
    EXPECT_NE(gl.output.find("on the GPU"), std::string::npos) << gl.output;
    EXPECT_GE(render::psnr(quilt(method + "_gl_qs2x2a1.5.png"), quilt(method + "_cpu_qs2x2a1.5.png")), 40.0);
  }
}

// --raster for voxel scenes: `lfd render --scene F.voxels --backend gl --raster compute` (the
// compute tile rasterizer, per view and V2LF's planes) gives the quilt of --raster hardware (the
// raster pipeline) and of the CPU; per view also --raster auto, which runs the voxel probe and
// prints its figures.
TEST_F(RenderBackendCli, VoxelComputeRasterMatchesHardwareAndTheCpu) {
  const std::string scene = (dir_ / "raster.voxels").string();
  ASSERT_EQ(test::run_lfd("scene generate --kind voxels --level 5 --out '" + scene + "'").exit_code, 0);
  for (const std::string method : {"per-view", "v2lf"}) {
    SCOPED_TRACE(method);
    const std::string common = "render --scene '" + scene + "' --method " + method +
                               " --views 4 --cols 2 --rows 2 --size 48x32 --chunks 16 --precision f32 --out '";
    const auto name = [&](const std::string& path) { return method + "_" + path + ".png"; };
    const auto cpu = test::run_lfd(common + (dir_ / name("cpu")).string() + "' --backend cpu");
    ASSERT_EQ(cpu.exit_code, 0) << cpu.output;
    for (const std::string path : {"hardware", "compute", "auto"}) {
      if (path == "auto" && method != "per-view") continue;  // one probe is enough
      const auto r = test::run_lfd(common + (dir_ / name(path)).string() + "' --backend gl --raster " + path);
      ASSERT_EQ(r.exit_code, 0) << r.output;
      // auto measures voxels, not Gaussians (gpu/probes/gl_raster_probe.hpp), and says so.
      if (path == "auto") {
        EXPECT_NE(r.output.find(" for voxels (probe quilt: compute "), std::string::npos) << r.output;
      }
    }
    const auto q = [&](const std::string& path) { return quilt(method + "_" + path + "_qs2x2a1.5.png"); };
    if (method == "per-view") {
      EXPECT_GE(render::psnr(q("auto"), q("cpu")), 40.0);
    }
    const double compute_hardware = render::psnr(q("compute"), q("hardware"));
    const double compute_cpu = render::psnr(q("compute"), q("cpu"));
    std::printf("voxels %s: compute vs hardware %.1f dB, compute vs CPU %.1f dB\n", method.c_str(), compute_hardware,
                compute_cpu);
    EXPECT_GE(compute_hardware, 40.0);
    EXPECT_GE(compute_cpu, 40.0);
  }
}

// `lfd bench voxels --raster hardware,compute`: both paths in one run, one table each in the
// JSON; V2LF's PSNR against each path's own per-view quilt is the same (both quilts are the
// CPU's); the CPU has no raster paths (exit 2).
TEST_F(RenderBackendCli, BenchVoxelsRunsBothRasterPaths) {
  const fs::path json = dir_ / "voxels.json";
  const auto r = test::run_lfd("bench voxels --backend gl --raster hardware,compute --level 5 --views 2 --size 32 "
                               "--chunks 64 --runs 1 --warmup 0 --json '" + json.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(json);
  const nlohmann::json result = nlohmann::json::parse(in);
  ASSERT_EQ(result["rasters"].size(), 2u);
  EXPECT_EQ(result["rasters"][0]["raster"], "hardware");
  EXPECT_EQ(result["rasters"][1]["raster"], "compute");
  const auto v2lf_db = [&](int path) {
    return result["rasters"][path]["result"]["tables"][0]["rows"][1]["psnr_db"].get<double>();
  };
  EXPECT_NEAR(v2lf_db(0), v2lf_db(1), 0.05);
  const auto cpu = test::run_lfd("bench voxels --backend cpu --raster compute --level 5 --views 2 --size 32");
  EXPECT_EQ(cpu.exit_code, 2) << cpu.output;
}

// `lfd bench direct --backend gl --plane-major`: the compute direct pass walking the planes with a
// barrier a plane is timed in the same rounds (its own column and JSON field); the CPU has no such
// pass (exit 2).
TEST_F(RenderBackendCli, BenchDirectTimesThePlaneMajorWalk) {
  const fs::path json = dir_ / "direct.json";
  const std::string go = (test::project_data() / "displays" / "go.visual.json").string();
  const std::string common = "bench direct --calibration '" + go +
                             "' --generated 2000 --view-height 64 --chunks 8 --runs 1 --warmup 0 --reference-views 0 "
                             "--plane-major";
  const auto r = test::run_lfd(common + " --backend gl --json '" + json.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("| GL direct pass, plane-major [s] |"), std::string::npos) << r.output;
  std::ifstream in(json);
  const nlohmann::json result = nlohmann::json::parse(in);
  EXPECT_GT(result["tables"][0]["rows"][0]["direct_pass_plane_major_seconds"]["median"].get<double>(), 0.0);
  const auto cpu = test::run_lfd(common + " --backend cpu");
  EXPECT_EQ(cpu.exit_code, 2) << cpu.output;
  EXPECT_NE(cpu.output.find("--plane-major"), std::string::npos) << cpu.output;
}

// `lfd render --direct --backend gl`: the panel from the compute direct pass against the CPU's
// direct pass on the same options (f32 planes, the default bilinear filter), for a Gaussian and a
// voxel scene on the Go.
TEST_F(RenderBackendCli, DirectPanelsOnTheGpuMatchTheCpu) {
  const std::string voxels = (dir_ / "scene.voxels").string();
  ASSERT_EQ(test::run_lfd("scene generate --kind voxels --level 5 --out '" + voxels + "'").exit_code, 0);
  const std::string go = (test::project_data() / "displays" / "go.visual.json").string();
  for (const auto& [scene, method] : {std::pair<std::string, std::string>{(test::project_data() / "scenes" / "demo.ply").string(), "g2lf"},
                                      std::pair<std::string, std::string>{voxels, "v2lf"}}) {
    SCOPED_TRACE(method);
    const std::string common = "render --scene '" + scene + "' --calibration '" + go +
                               "' --size 72x128 --views 8 --chunks 16 --precision f32 --direct --panel '";
    const auto cpu = test::run_lfd(common + (dir_ / (method + "_cpu.png")).string() + "' --backend cpu");
    ASSERT_EQ(cpu.exit_code, 0) << cpu.output;
    const auto gl = test::run_lfd(common + (dir_ / (method + "_gl.png")).string() + "' --backend gl");
    ASSERT_EQ(gl.exit_code, 0) << gl.output;
    const ImageF a = quilt(method + "_gl.png"), b = quilt(method + "_cpu.png");
    ASSERT_EQ(a.width, 1440);
    ASSERT_EQ(a.height, 2560);
    const double db = render::psnr(a, b);
    std::printf("  lfd render --direct, %s, GL against CPU: %.1f dB\n", method.c_str(), db);
    EXPECT_GE(db, 40.0);
  }
}

}  // namespace
}  // namespace lfd
