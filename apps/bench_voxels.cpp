// lfd bench voxels: per-view voxel quilts against V2LF (bench/voxel_benchmark.hpp).
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/backend.hpp"
#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/bench_renderers.hpp"
#include "bench/voxel_benchmark.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

int RunBenchVoxels(int argc, char** argv) {
  CLI::App app{
      "Per-view voxel quilts (SVR's, with the scene's supersampling) against V2LF on the CPU or the GPU\n"
      "(--backend gl), in one process on the same scene: per configuration the median frame time of repeated runs after\n"
      "warm-up and its spread, FPS, the speed-up, PSNR/SSIM against the per-view quilt, plane memory\n"
      "and peak memory. Configurations: the paper's Table 1 (table1), N_chunk 128 and 256 (chunks),\n"
      "32-bit planes (f32), planes at view density (density). Scene: --scene, else a generated tabletop.\n"
      "\nExamples:\n"
      "  lfd bench voxels --views 9 --size 256\n"
      "  lfd bench voxels --backend gl --views 45 --size 512\n"
      "  lfd bench voxels --backend gl --raster hardware,compute --views 9 --size 128   (both GL raster paths, one run)\n"
      "  lfd bench voxels --scene demo.voxels --camera cam.json --views 45 --size 512 --json v2lf.json",
      "voxels"};
  bench::VoxelBenchOptions o;
  std::string json_path;
  bool no_lowpass = false;
  app.add_option("--scene", o.scene_path, "voxel scene (.voxels, svraster-webgl .ply); default: generated");
  app.add_option("--level", o.generated_level, "the generated tabletop's finest octree level")->capture_default_str();
  app.add_option("--camera", o.camera_path,
                 "cam.json (default: the tabletop camera of docs/voxels.md for the generated scene, else "
                 "the voxel scene's default camera)");
  app.add_option("--views", o.views, "view counts, comma-separated")->delimiter(',')->capture_default_str();
  app.add_option("--size", o.size, "view width = height in pixels")->capture_default_str();
  app.add_option("--view-cone", o.view_cone_deg, "view cone in degrees")->capture_default_str();
  app.add_option("--binning", o.binnings, "chunk binnings: quantile (the paper's), mixed")
      ->delimiter(',')->capture_default_str();
  app.add_option("--configs", o.config_sets, "configuration sets: table1, chunks, f32, density")
      ->delimiter(',')->capture_default_str();
  app.add_option("--chunks", o.only_chunks, "only the configurations with this N_chunk (0: all)")->capture_default_str();
  app.add_option("--split-levels", o.split_levels, "V2LF: split voxels straddling a chunk boundary, levels deeper")
      ->capture_default_str();
  app.add_flag("--no-plane-lowpass", no_lowpass, "V2LF: no low-pass filter on the planes");
  app.add_option("--runs", o.runs, "timed frames per configuration (default: CPU 3, GL 10)");
  app.add_option("--warmup", o.warmup, "untimed frames before them")->capture_default_str();
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  std::string backend = "cpu";
  app.add_option("--backend", backend, "renderer: cpu, or gl (the GL voxel path through headless EGL; exit 2 without it)")
      ->check(CLI::IsMember({"cpu", "gl"}))->capture_default_str();
  std::vector<std::string> rasters{"hardware"};
  add_bench_raster_option(app, rasters, "voxels (per view and V2LF's planes)");
  if (auto code = parse(app, argc, argv)) return *code;
  o.plane_lowpass = !no_lowpass;
  o.check();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows appear as they finish, also in a log file

  // One table per raster path (one: the table alone; several: {"rasters": [...]}).
  const nlohmann::ordered_json result = run_per_raster(app, rasters, backend, [&](gpu::RasterPath raster) {
    const bench::BenchRenderers renderers = bench::make_bench_renderers(backend, scene::SceneKind::kVoxels, raster);
    return bench::run_voxel_benchmark(*renderers.per_view, *renderers.sweeping, o);
  });
  if (!json_path.empty()) {
    write_text_atomic(json_path, result.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
