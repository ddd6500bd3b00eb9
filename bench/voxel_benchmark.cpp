#include "bench/voxel_benchmark.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>

#include <fmt/format.h>

#include "bench/render_configs.hpp"
#include "bench/timing_stats.hpp"
#include "display/display_quilt.hpp"
#include "render/camera_json.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "util/error.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_io.hpp"

namespace lfd::bench {
namespace {

using Clock = std::chrono::steady_clock;

// The generated tabletop's camera (docs/voxels.md): elevated, in the empty space inside the
// sky shell, objects filling the view.
render::CameraSpec tabletop_voxel_camera() {
  render::CameraSpec s;
  s.position = glm::vec3(0.0f, -1.5f, -5.5f);
  s.look_at = glm::vec3(0.0f, 0.5f, 0.0f);
  s.up = glm::vec3(0.0f, -1.0f, 0.0f);
  s.fov_y_deg = 45.0f;
  return s;
}

struct Measured {
  TimingStats seconds;
  size_t peak_bytes = 0;
  ImageF quilt;                    // the last frame's
  std::optional<voxel::V2lfStats> v2lf;
};

// Warm-up, then the timed frames (`frame` returns V2LF's stats, if it is V2LF); the quilt is
// read back after them, untimed.
Measured measure(VoxelQuiltRenderer& renderer, const std::function<std::optional<voxel::V2lfStats>()>& frame,
                 int warmup, int runs) {
  Measured m;
  renderer.reset_peak_memory();
  for (int w = 0; w < warmup; ++w) frame();
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    m.v2lf = frame();
    t.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  m.peak_bytes = renderer.peak_memory_bytes();
  m.seconds = summarize(t);
  m.quilt = renderer.read_quilt();
  return m;
}

std::string v2lf_label(const G2lfConfig& c) {
  std::string name = c.name;
  if (name.rfind("G2LF", 0) == 0) name.replace(0, 4, "V2LF");
  return name;
}

}  // namespace

void VoxelBenchOptions::check() const {
  const auto fail = [](const std::string& field, const std::string& problem) {
    throw_input_error("voxel benchmark: {}: {}", field, problem);
  };
  if (scene_path.empty()) {
    voxel::VoxelGeneratorOptions g;
    g.detail_level = generated_level;
    g.check();
  }
  if (views.empty()) fail("views", "no view count");
  for (int v : views)
    if (v < 1 || v > 256) fail("views", fmt::format("{} is outside 1..256", v));
  if (size < 16 || size > 4096) fail("size", fmt::format("{} is outside 16..4096", size));
  if (!(view_cone_deg > 0.0f && view_cone_deg < 170.0f))
    fail("view_cone_deg", fmt::format("{} is outside (0, 170)", view_cone_deg));
  for (const std::string& b : binnings) render::parse_chunk_binning(b);
  g2lf_configs_in(config_sets, "voxel benchmark: config_sets");
  if (split_levels < 0 || split_levels > 4) fail("split_levels", fmt::format("{} is outside 0..4", split_levels));
  if (runs < 0 || runs > 1000) fail("runs", fmt::format("{} is outside 1..1000 (0: the backend's default)", runs));
  if (warmup < 0 || warmup > 100) fail("warmup", fmt::format("{} is outside 0..100", warmup));
}

nlohmann::ordered_json run_voxel_benchmark(VoxelQuiltRenderer& renderer, const VoxelBenchOptions& options) {
  options.check();
  const int runs = options.runs > 0 ? options.runs : renderer.default_runs();
  const auto t_load = Clock::now();
  voxel::VoxelScene scene;
  std::string label;
  if (!options.scene_path.empty()) {
    scene = voxel::load_voxel_scene(options.scene_path);
    label = std::filesystem::path(options.scene_path).filename().string();
  } else {
    voxel::VoxelGeneratorOptions g;
    g.detail_level = options.generated_level;
    scene = voxel::generate_voxel_scene(g);
    label = fmt::format("generated tabletop (level {})", options.generated_level);
  }
  const double load_seconds = std::chrono::duration<double>(Clock::now() - t_load).count();
  renderer.set_scene(scene);
  const render::CameraSpec spec = !options.camera_path.empty() ? render::read_camera_json(options.camera_path)
                                  : options.scene_path.empty() ? tabletop_voxel_camera()
                                                               : voxel::frame_voxel_scene(scene, 40.0f);
  const render::Camera base = render::camera_from_spec(spec, options.size, options.size);

  nlohmann::ordered_json out = {{"benchmark", "voxels"},
                                {"backend", renderer.name()},
                                {"device", renderer.device()},
                                {"memory", renderer.memory_kind()},
                                {"scene", label},
                                {"voxels", scene.size()},
                                {"supersampling", scene.supersampling},
                                {"samples_per_voxel", scene.samples_per_voxel},
                                {"load_seconds", load_seconds},
                                {"runs", runs},
                                {"warmup", options.warmup},
                                {"size", options.size},
                                {"view_cone_deg", options.view_cone_deg},
                                {"split_levels", options.split_levels},
                                {"plane_lowpass", options.plane_lowpass},
                                {"tables", nlohmann::ordered_json::array()}};
  std::printf("lfd bench voxels: %s (%s); median of %d frames after %d warm-up; peak memory: %s; PSNR/SSIM "
              "against the per-view quilt of the same backend\n",
              renderer.name().c_str(), renderer.device().c_str(), runs, options.warmup,
              renderer.memory_kind().c_str());
  for (int views : options.views) {
    const render::QuiltGeometry geometry = render::make_quilt_geometry(
        base, glm::length(spec.look_at - spec.position), options.view_cone_deg, views);
    const display::QuiltGrid grid = display::quilt_grid_for_views(views, 1.0);
    const render::QuiltLayout layout = render::make_quilt_layout(geometry, grid.cols, grid.rows);
    // V2LF's default D_shift: the reference camera at the base camera.
    const float d_forward = render::make_reference_camera(geometry, 0.0f, 1).d_forward;
    std::printf("\n#### %s: %zu voxels (ss %.2g, K %d), %d views of %dx%d (%dx%d quilt), view cone %.0f deg, "
                "split levels %d, plane low-pass %s\n\n",
                label.c_str(), scene.size(), scene.supersampling, scene.samples_per_voxel, views, options.size,
                options.size, layout.width, layout.height, options.view_cone_deg, options.split_levels,
                options.plane_lowpass ? "on" : "off");
    std::printf("| method | binning | median [s] | min-max [s] | FPS | speed-up | planes [GB] | peak [GB] | "
                "PSNR [dB] | SSIM |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    nlohmann::ordered_json table = {{"views", views},
                                    {"grid", {grid.cols, grid.rows}},
                                    {"quilt", {layout.width, layout.height}},
                                    {"rows", nlohmann::ordered_json::array()}};
    const Measured truth = measure(
        renderer,
        [&]() -> std::optional<voxel::V2lfStats> {
          renderer.render_per_view(geometry, layout);
          return std::nullopt;
        },
        options.warmup, runs);
    const auto print_row = [&](const std::string& method, const std::string& binning, const Measured& m,
                               std::optional<std::pair<double, double>> quality) {
      const double speedup = truth.seconds.median / m.seconds.median;
      const size_t plane_bytes = m.v2lf ? m.v2lf->plane_bytes : 0;
      std::printf("| %s | %s | %.3f | %.3f-%.3f | %.2f | %.1fx | %s | %.3f | %s | %s |\n", method.c_str(),
                  binning.c_str(), m.seconds.median, m.seconds.min, m.seconds.max, 1.0 / m.seconds.median, speedup,
                  plane_bytes ? fmt::format("{:.3f}", double(plane_bytes) / 1e9).c_str() : "-",
                  double(m.peak_bytes) / 1e9, quality ? fmt::format("{:.2f}", quality->first).c_str() : "-",
                  quality ? fmt::format("{:.4f}", quality->second).c_str() : "-");
      std::fflush(stdout);
      nlohmann::ordered_json r = {{"method", method},
                                  {"binning", binning},
                                  {"seconds", m.seconds.to_json()},
                                  {"fps", 1.0 / m.seconds.median},
                                  {"speedup", speedup},
                                  {"peak_bytes", m.peak_bytes},
                                  {"plane_bytes", plane_bytes},
                                  {"psnr_db", quality ? nlohmann::ordered_json(quality->first) : nullptr},
                                  {"ssim", quality ? nlohmann::ordered_json(quality->second) : nullptr}};
      if (m.v2lf) {
        r["planes"] = m.v2lf->planes;
        r["voxels_binned"] = m.v2lf->voxels_binned;
        r["voxels_split"] = m.v2lf->voxels_split;
        r["stage_seconds_last"] = {{"binning", m.v2lf->seconds_binning},
                                   {"planes", m.v2lf->seconds_planes},
                                   {"swizzle", m.v2lf->seconds_swizzle}};
      }
      return r;
    };
    table["rows"].push_back(print_row("per-view SVR (ground truth)", "-", truth, std::nullopt));
    for (const std::string& binning : options.binnings)
      for (const G2lfConfig& c : g2lf_configs_in(options.config_sets, "voxel benchmark: config_sets")) {
        if (options.only_chunks > 0 && c.chunks != options.only_chunks) continue;
        voxel::V2lfOptions o;
        o.planes.binning = render::parse_chunk_binning(binning);
        o.planes.chunks = c.chunks;
        o.planes.plane_scale = c.plane_scale > 0 ? c.plane_scale : equal_density_plane_scale(geometry, d_forward);
        o.planes.filter = c.filter;
        o.planes.precision = c.precision;
        o.planes.adaptive_filter = options.plane_lowpass;
        o.split_levels = options.split_levels;
        const Measured m = measure(
            renderer, [&]() -> std::optional<voxel::V2lfStats> { return renderer.render_v2lf(geometry, layout, o); },
            options.warmup, runs);
        nlohmann::ordered_json r =
            print_row(v2lf_label(c), binning, m,
                      std::make_pair(render::psnr(m.quilt, truth.quilt), render::ssim(m.quilt, truth.quilt)));
        r["config_set"] = c.set;
        r["chunks"] = c.chunks;
        r["plane_scale"] = o.planes.plane_scale;
        r["filter"] = c.filter == render::PlaneFilter::kBilinear ? "bilinear" : "nearest";
        r["precision"] = c.precision == render::PlanePrecision::kF32 ? "f32" : "u8";
        table["rows"].push_back(std::move(r));
      }
    out["tables"].push_back(std::move(table));
  }
  return out;
}

}  // namespace lfd::bench
