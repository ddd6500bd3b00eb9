// lfd bench direct: the direct panel pass against the quilt path (bench/direct_benchmark.hpp).
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/bench_renderers.hpp"
#include "bench/direct_baseline_benchmark.hpp"
#include "bench/direct_benchmark.hpp"
#include "render/g2lf.hpp"
#include "util/atomic_file.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"

namespace lfd::apps {
namespace {

// --baseline: the per-view direct table (CPU only: the masks drive the CPU rasterizer).
int RunDirectBaseline(const bench::DirectBenchOptions& o, const std::vector<int>& views, const std::string& backend,
                      const std::string& json_path) {
  if (backend != "cpu") throw_input_error("--baseline: the per-view direct baseline runs on --backend cpu only");
  bench::DirectBaselineOptions b;
  b.calibrations = o.calibrations;
  b.scenes = o.scenes;
  b.chunks = o.chunks.front();
  if (o.runs > 0) b.runs = o.runs;
  b.warmup = o.warmup;
  b.view_height = o.view_height;
  b.direct_filter = o.direct_filter;
  b.views = views;
  const bench::BenchRenderers renderers = bench::make_bench_renderers(backend, scene::SceneKind::kGaussians);
  const nlohmann::ordered_json result = bench::run_direct_baseline_benchmark(*renderers.sweeping, b);
  if (!json_path.empty()) {
    write_text_atomic(json_path, result.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace

int RunBenchDirect(int argc, char** argv) {
  CLI::App app{
      "The direct panel pass (every subpixel composited from the sweeping planes at its own view\n"
      "offset, no quilt) against the quilt path (swizzle blend, then the interlacer) on one backend,\n"
      "the runs alternating: per display, scene and N_chunk the median time after the planes and of\n"
      "the whole frame, the quilt's memory, and PSNR over the panel against a continuous reference\n"
      "(per-view renders at --reference-views views, nearest view per subpixel) for the direct panel\n"
      "and the quilt path with nearest and linear view blending.\n"
      "\nExamples:\n"
      "  lfd bench direct --quick\n"
      "  lfd bench direct --chunks 16,64,256 --json direct.json\n"
      "  lfd bench direct --scene ../shared/data/scenes/guitar.compressed.ply --generated 0 --reference-views 0\n"
      "  lfd bench direct --method v2lf --voxel-level 8 --reference-views 0\n"
      "  lfd bench direct --baseline   (per-view direct: the views rasterised only where the panel reads them)",
      "direct"};
  bench::DirectBenchOptions o;
  std::string backend = "cpu", json_path;
  std::vector<std::string> scene_files;
  std::vector<size_t> generated = {100000};
  const std::filesystem::path displays = data_dir() / "displays";
  o.calibrations = {(displays / "portrait.visual.json").string(), (displays / "16in-landscape-gen3.visual.json").string(),
                    (displays / "go.visual.json").string()};
  bool quick = false;
  std::string method = "g2lf";
  std::vector<int> voxel_levels = {8};
  app.add_option("--method", method,
                 "the planes: g2lf (Gaussian scenes) or v2lf (voxel scenes: --scene files are voxel scenes, "
                 "--voxel-level the generated ones)")
      ->check(CLI::IsMember({"g2lf", "v2lf"}))->capture_default_str();
  app.add_option("--voxel-level", voxel_levels,
                 "with --method v2lf: finest levels of generated voxel tabletops, comma-separated (0: none)")
      ->delimiter(',')->capture_default_str();
  std::string direct_filter = "bilinear";
  app.add_option("--direct-filter", direct_filter,
                 "the direct pass's plane sampling, nearest or bilinear (the quilt path: nearest, then the "
                 "interlacer's bilinear lookup)")
      ->check(CLI::IsMember({"nearest", "bilinear"}))->capture_default_str();
  std::string direct_sampler = "unit";
  app.add_option("--direct-sampler", direct_sampler,
                 "--backend gl, bilinear planes: the texture unit filters (unit: one fetch, its own weights) or "
                 "the shader by hand (shader: four texelFetch, the CPU's weights)")
      ->check(CLI::IsMember({"unit", "shader"}))->capture_default_str();
  std::string direct_kernel = render::sample_kernel_name(render::sample_window_kernel());
  app.add_option("--direct-kernel", direct_kernel,
                 "--backend cpu: the direct pass's sampling loop, scalar or avx2 (eight rays a step with "
                 "gathers; the default where the CPU has AVX2)")
      ->check(CLI::IsMember({"scalar", "avx2"}))->capture_default_str();
  app.add_flag("--plane-major", o.plane_major,
               "--backend gl: also time the compute direct pass with a barrier after every plane (the whole "
               "panel tile reads plane k before plane k + 1, the swizzle's order), in the same rounds");
  app.add_option("--backend", backend, "renderer: cpu, or gl (OpenGL 4.5 through headless EGL; exit 2 without it)")
      ->check(CLI::IsMember({"cpu", "gl"}))->capture_default_str();
  app.add_option("--calibration", o.calibrations, "displays (visual.json or calibration.json), comma-separated")
      ->delimiter(',')->capture_default_str();
  app.add_option("--scene", scene_files, "scene files (repeatable; a missing one is skipped with a message)");
  app.add_option("--generated", generated, "Gaussians of generated tabletop scenes, comma-separated (0: none)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--chunks", o.chunks, "N_chunk of each row, comma-separated")->delimiter(',')->capture_default_str();
  app.add_option("--plane-scale", o.plane_scale, "the planes' resolution scale P_s of every row")->capture_default_str();
  app.add_option("--runs", o.runs, "timed frames per side and row (0: the backend's default)")->capture_default_str();
  app.add_option("--warmup", o.warmup, "untimed frames of each side first")->capture_default_str();
  app.add_option("--reference-views", o.reference_views,
                 "views of the continuous reference (per-view renders; 0: no PSNR)")->capture_default_str();
  app.add_option("--view-height", o.view_height, "view height in pixels (width: the display's aspect)")
      ->capture_default_str();
  app.add_flag("--quick", quick,
               "a short run: the Go only, 20k Gaussians (v2lf: voxel level 7), 64 reference views, 2 runs");
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  bool baseline = false;
  app.add_flag("--baseline", baseline,
               "instead: the per-view direct baseline (CPU): each view rasterised only where the panel reads "
               "it (mask from the interlacer's lookup), then interlaced, against the full views and the direct "
               "pass at the first --chunks (bench/direct_baseline_benchmark.hpp)");
  std::vector<int> baseline_views = {0};
  app.add_option("--baseline-views", baseline_views,
                 "--baseline: view counts of its rows, comma-separated (0: the display's recommendation)")
      ->delimiter(',')->capture_default_str();
  if (auto code = parse(app, argc, argv)) return *code;
  if (o.plane_major && backend != "gl") throw_input_error("bench direct: --plane-major: applies to --backend gl only");
  o.direct_filter = render::parse_plane_filter(direct_filter);
  o.direct_hardware_bilinear = direct_sampler == "unit";
  o.direct_kernel = render::parse_sample_kernel(direct_kernel);
  if (!render::sample_kernel_available(o.direct_kernel))
    throw_input_error("bench direct: --direct-kernel avx2: this CPU has no AVX2");
  const bool voxels = method == "v2lf";
  if (voxels && app.count("--generated")) throw_input_error("bench direct: --generated: applies to --method g2lf only");
  if (!voxels && app.count("--voxel-level")) throw_input_error("bench direct: --voxel-level: applies to --method v2lf only");
  o.kind = voxels ? scene::SceneKind::kVoxels : scene::SceneKind::kGaussians;
  if (quick) {
    if (!app.count("--calibration")) o.calibrations = {(displays / "go.visual.json").string()};
    if (!app.count("--generated")) generated = scene_files.empty() ? std::vector<size_t>{20000} : std::vector<size_t>{};
    if (!app.count("--voxel-level")) voxel_levels = scene_files.empty() ? std::vector<int>{7} : std::vector<int>{};
    if (!app.count("--reference-views")) o.reference_views = 64;
    if (!app.count("--runs")) o.runs = 2;
  }
  for (const std::string& f : scene_files) o.scenes.push_back({f, 0});
  if (voxels) {
    for (int level : voxel_levels)
      if (level > 0) o.scenes.push_back({"", size_t(level)});
  } else {
    for (size_t n : generated)
      if (n > 0) o.scenes.push_back({"", n});
  }
  o.check();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  if (baseline && voxels) throw_input_error("bench direct: --baseline: applies to --method g2lf only");
  if (baseline) return RunDirectBaseline(o, baseline_views, backend, json_path);

  const bench::BenchRenderers renderers = bench::make_bench_renderers(backend, o.kind);
  const nlohmann::ordered_json result = bench::run_direct_benchmark(
      *renderers.sweeping, o.reference_views > 0 ? renderers.per_view.get() : nullptr, o);
  if (!json_path.empty()) {
    write_text_atomic(json_path, result.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
