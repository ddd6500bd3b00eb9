// `lfd bench gpu-frame`: the GL frame, both sides of each GPU-side change in one run
// (bench/gpu_frame_benchmark.hpp; docs/gpu.md "A frame that never waits").
//   lfd bench gpu-frame --scene data/scenes/demo.ply --views 45 --size 256
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/backend.hpp"
#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/gpu_frame_benchmark.hpp"
#include "render/preprocess.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

int RunBenchGpuFrame(int argc, char** argv) {
  CLI::App app{"The GL frame on one headless context, each variant in the same run: G2LF and per view\n"
               "with their stage timers waited for at the end of each frame (the CPU waits for the GPU)\n"
               "and read a few frames late (frames issued back to back), and the G2LF swizzle with\n"
               "1 view per invocation against several, and both ways of drawing the Gaussians (--raster).\n"
               "Medians of --runs after --warmup.\n"
               "\nExample (docs/performance.md):\n"
               "  lfd bench gpu-frame --scene data/scenes/demo.ply --views 45 --size 256",
               "gpu-frame"};
  std::string json_path, scene_path;
  int size = 256, generated = 0;
  float zoom = 1.0f;
  bench::GpuFrameOptions o;
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  app.add_option("--scene", scene_path, "a Gaussian scene file, framed automatically");
  app.add_option("--generated", generated, "Gaussians of the generated tabletop instead of a file")
      ->check(CLI::Range(1, 100000000));
  app.add_option("--size", size, "view width = height in pixels")->capture_default_str()->check(CLI::Range(8, 4096));
  app.add_option("--views", o.views, "views in one row")->capture_default_str()->check(CLI::Range(1, 256));
  app.add_option("--chunks", o.chunks, "G2LF's N_chunk")->capture_default_str()->check(CLI::Range(1, 2048));
  app.add_option("--runs", o.runs, "timed runs per variant")->capture_default_str()->check(CLI::Range(1, 1000));
  app.add_option("--warmup", o.warmup, "untimed runs before them")->capture_default_str()->check(CLI::Range(0, 100));
  app.add_option("--batch", o.batch, "frames issued back to back per run when the timers are read late")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  app.add_option("--swizzle-views", o.swizzle_views, "G2LF swizzle variants: views per invocation, comma-separated")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  app.add_flag("--sort-only", o.sort_only,
               "the sort rows instead: all N against the visible (binned) Gaussians, float against normalised keys");
  app.add_option("--zoom", zoom,
                 "narrow the framed view's field of view this many times (a part of the scene in view: "
                 "the others culled, what the sort rows compare)")
      ->capture_default_str()
      ->check(CLI::Range(1.0f, 100.0f));
  app.add_option("--voxel-level", o.voxel_level, "finest level of the generated voxel scene of the V2LF rows (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 11));
  app.add_option("--planes", o.planes, "G2LF plane raster variants: batched, layered, layered-rgba8, comma-separated")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"batched", "layered", "layered-rgba8"}));
  std::vector<std::string> table{"off", "on"}, hardware{"off", "on"};
  app.add_option("--swizzle-table", table, "G2LF swizzle views x planes table variants: off, on, comma-separated")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"off", "on"}));
  app.add_option("--hardware-bilinear", hardware, "G2LF bilinear swizzle variants: off (by hand), on (texture unit)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"off", "on"}));
  std::vector<std::string> rasters{"hardware", "compute"};
  app.add_option("--raster", rasters,
                 "how the Gaussians are drawn: hardware (the variants above), compute (G2LF's planes and the "
                 "per-view quilt by the compute tile rasterizer), comma-separated")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"hardware", "compute"}));
  bool no_per_view = false;
  app.add_flag("--no-per-view", no_per_view, "G2LF rows only (the per-view ones take seconds a frame on llvmpipe)");
  if (auto code = parse(app, argc, argv)) return *code;
  o.per_view = !no_per_view;
  o.rasters.clear();
  for (const std::string& r : rasters) o.rasters.push_back(gpu::parse_raster_path(r));
  o.swizzle_table.clear();
  for (const std::string& t : table) o.swizzle_table.push_back(t == "on");
  o.hardware_bilinear.clear();
  for (const std::string& h : hardware) o.hardware_bilinear.push_back(h == "on");
  if (scene_path.empty() == (generated == 0)) {
    std::fprintf(stderr, "lfd bench gpu-frame: error: give one of --scene and --generated\n");
    return 2;
  }

  const auto context = open_backend(lightfield::BackendChoice::kGl, false);
  std::printf("backend: gl on %s\n", context->info().summary().c_str());
  bench::GlVsCpuScene scene =
      scene_path.empty() ? bench::gl_vs_cpu_tabletop(generated, size) : bench::gl_vs_cpu_scene_file(scene_path, size);
  scene.base.fov_x_rad = 2.0f * std::atan(scene.base.tan_half_fov_x() / zoom);
  scene.base.fov_y_rad = 2.0f * std::atan(scene.base.tan_half_fov_y() / zoom);
  std::printf("%s (%zu Gaussians), %d views of %dx%d, N_chunk %d, %d runs after %d warm-up\n", scene.name.c_str(),
              scene.scene.size(), o.views, scene.base.width, scene.base.height, o.chunks, o.runs, o.warmup);
  const auto projected = render::preprocess(scene.scene, scene.base, render::RasterSettings{});
  const auto visible = std::count_if(projected.begin(), projected.end(), [](const auto& p) { return p.radius_px > 0; });
  std::printf("zoom %.1f: %td of the Gaussians visible in the centre view (the sort rows sort these)\n", zoom, visible);
  const auto rows = bench::run_gpu_frame(scene, o, context->info());
  std::fputs(bench::gpu_frame_table(rows).c_str(), stdout);
  if (!json_path.empty()) {
    auto j = nlohmann::ordered_json{{"renderer", context->info().summary()}, {"rows", bench::gpu_frame_json(rows)}};
    write_text_atomic(json_path, j.dump(2) + "\n");
    std::printf("wrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
