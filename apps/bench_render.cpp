// lfd bench render: per-view quilts against G2LF on one backend (bench/render_benchmark.hpp).
#include <cstdio>

#include <nlohmann/json.hpp>

#include "util/default_display.hpp"
#include "apps/backend.hpp"
#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/bench_renderers.hpp"
#include "bench/render_benchmark.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::apps {

int RunBenchRender(int argc, char** argv) {
  CLI::App app{
      "Per-view quilt rendering against G2LF on one backend, in one process on the same scenes:\n"
      "per configuration the median frame time of repeated runs after warm-up and its spread,\n"
      "FPS, the speed-up over the per-view quilt, the time with the PNG written, PSNR/SSIM\n"
      "against the per-view quilt, plane memory and peak memory. Configurations: the paper's\n"
      "Table 1 (table1), N_chunk 128 and 256 (chunks), 32-bit planes (f32), and planes at view\n"
      "density (density: the smallest P_s whose texel on the focal plane is no larger than a view\n"
      "pixel). Scenes: --scene files and generated tabletop scenes (--generated).\n"
      "\nExamples:\n"
      "  lfd bench render --quick\n"
      "  lfd bench render --generated 100000,1000000,3000000 --json render.json\n"
      "  lfd bench render --scene guitar.compressed.ply --generated 0 --views 45 --configs table1\n"
      "  lfd bench render --backend gl --generated 1000000 --views 45 --size 512x910 --chunks 64,256,512 --plane-scale 1\n"
      "  lfd bench render --backend gl --raster hardware,compute --quick   (both GL raster paths, one run)",
      "render"};
  bench::RenderBenchOptions o;
  std::string backend = "cpu", json_path;
  std::vector<std::string> scene_files;
  std::vector<size_t> generated = {100000, 1000000};
  bool quick = false, no_per_view = false;
  std::vector<std::string> rasters{"hardware"};
  app.add_option("--backend", backend, "renderer: cpu, or gl (OpenGL 4.5 through headless EGL; exit 2 without it)")
      ->check(CLI::IsMember({"cpu", "gl"}))->capture_default_str();
  add_bench_raster_option(app, rasters, "Gaussians");
  app.add_option("--scene", scene_files, "scene files to render (repeatable)");
  app.add_option("--generated", generated,
                 "Gaussians of generated tabletop scenes, comma-separated (0: none)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--views", o.views, "view counts, comma-separated")->delimiter(',')->capture_default_str();
  std::string size = "512";
  app.add_option("--size", size, "the views' size: N (N x N pixels) or WxH (the paper's 512x910)")
      ->capture_default_str();
  app.add_option("--view-cone", o.view_cone_deg, "view cone in degrees")->capture_default_str();
  app.add_option("--shift", o.shift_fraction,
                 "D_shift as a fraction of D_forward (1: reference camera at the base camera; 0: the paper's)")
      ->capture_default_str();
  app.add_option("--binning", o.binnings, "chunk binnings: quantile (the paper's), mixed (lfd render's default)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--configs", o.config_sets, "configuration sets: table1, chunks, f32, density")
      ->delimiter(',')->capture_default_str();
  app.add_option("--chunks", o.only_chunks, "only the configurations with these N_chunk, comma-separated (0: all)")
      ->delimiter(',');
  app.add_option("--plane-scale", o.only_plane_scale, "only the configurations with this P_s (0: all)")
      ->capture_default_str();
  app.add_option("--runs", o.runs, "timed frames per configuration (0: the backend's default, CPU 3)")
      ->capture_default_str();
  app.add_option("--warmup", o.warmup, "untimed frames before them")->capture_default_str();
  app.add_option("--png-runs", o.png_runs,
                 "of the timed frames, how many also write the quilt PNG (the +PNG column; 0: none)")
      ->capture_default_str();
  app.add_flag("--no-per-view", no_per_view, "G2LF only: no per-view quilt, so no speed-up, PSNR or SSIM");
  app.add_flag("--tabletop-camera", o.tabletop_camera,
               "generated scenes: a person's tabletop framing (elevated, objects filling the view) "
               "instead of the default framing");
  app.add_flag("--quick", quick,
               "a short run: 100k generated Gaussians (unless --scene/--generated), 45 views, N_chunk 64");
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;

  if (quick) {
    if (app.count("--generated") == 0) generated = scene_files.empty() ? std::vector<size_t>{100000} : std::vector<size_t>{};
    if (app.count("--views") == 0) o.views = {kDefaultViewCount};
    if (app.count("--chunks") == 0) o.only_chunks = {64};
    if (app.count("--configs") == 0) o.config_sets = {"table1", "density"};
  }
  o.size = parse_view_size(size, "--size", true);
  std::erase(o.only_chunks, 0);
  for (const std::string& f : scene_files) o.scenes.push_back({f, 0});
  for (size_t n : generated)
    if (n > 0) o.scenes.push_back({"", n});
  o.per_view = !no_per_view;
  o.check();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows appear as they finish, also in a log file

  // One table per raster path (one: the table alone, as before; several: {"rasters": [...]}).
  const nlohmann::ordered_json result = run_per_raster(app, rasters, backend, [&](gpu::RasterPath raster) {
    const bench::BenchRenderers renderers = bench::make_bench_renderers(backend, scene::SceneKind::kGaussians, raster);
    return bench::run_render_benchmark(*renderers.per_view, *renderers.sweeping, o);
  });
  if (!json_path.empty()) {
    write_text_atomic(json_path, result.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
