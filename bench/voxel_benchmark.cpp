#include "bench/voxel_benchmark.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "bench/frame_timing.hpp"
#include "bench/render_configs.hpp"
#include "bench/timing_stats.hpp"
#include "display/display_quilt.hpp"
#include "lightfield/view_plan.hpp"
#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "util/error.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_generator.hpp"
#include "scene/voxel_io.hpp"
#include "util/stopwatch.hpp"

namespace lfd::bench {
namespace {

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

// A row's frames and the last quilt, read back after them (untimed).
struct Measured {
  FrameTimings timings;
  ImageF quilt;
};

Measured measure(lightfield::LightFieldRenderer& renderer, const render::QuiltGeometry& geometry,
                 const render::QuiltLayout& layout, int warmup, int runs) {
  Measured m;
  m.timings = time_frames(renderer, geometry, layout, {.warmup = warmup, .runs = runs, .png_runs = 0, .png_path = {}});
  m.quilt = renderer.take_quilt();
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

namespace {

struct LoadedScene {
  scene::Scene scene;
  std::string label;
  double load_seconds = 0;
};

LoadedScene load_scene(const VoxelBenchOptions& options) {
  const Stopwatch load;
  if (!options.scene_path.empty()) {
    scene::Scene scene(scene::load_voxel_scene(options.scene_path));
    return {std::move(scene), std::filesystem::path(options.scene_path).filename().string(),
            load.seconds()};
  }
  voxel::VoxelGeneratorOptions g;
  g.detail_level = options.generated_level;
  scene::Scene scene(voxel::generate_voxel_scene(g));
  return {std::move(scene), fmt::format("generated tabletop (level {})", options.generated_level),
          load.seconds()};
}

// Prints one table row and returns it as JSON (`v2lf`: with the planes' figures).
nlohmann::ordered_json print_row(const std::string& method, const std::string& binning, const Measured& m,
                                 const Measured& truth, bool v2lf, std::optional<std::pair<double, double>> quality) {
  const TimingStats& t = m.timings.render;
  const double speedup = truth.timings.render.median / t.median;
  const lightfield::QuiltStats last = m.timings.stats.empty() ? lightfield::QuiltStats{} : m.timings.stats.back();
  const size_t plane_bytes = v2lf ? last.plane_bytes : 0;
  std::printf("| %s | %s | %.3f | %.3f-%.3f | %.2f | %.1fx | %s | %.3f | %s | %s |\n", method.c_str(),
              binning.c_str(), t.median, t.min, t.max, 1.0 / t.median, speedup,
              plane_bytes ? fmt::format("{:.3f}", double(plane_bytes) / 1e9).c_str() : "-",
              double(m.timings.peak_bytes) / 1e9, quality ? fmt::format("{:.2f}", quality->first).c_str() : "-",
              quality ? fmt::format("{:.4f}", quality->second).c_str() : "-");
  std::fflush(stdout);
  nlohmann::ordered_json r = {{"method", method},
                              {"binning", binning},
                              {"seconds", t.to_json()},
                              {"fps", 1.0 / t.median},
                              {"speedup", speedup},
                              {"peak_bytes", m.timings.peak_bytes},
                              {"plane_bytes", plane_bytes},
                              {"psnr_db", quality ? nlohmann::ordered_json(quality->first) : nullptr},
                              {"ssim", quality ? nlohmann::ordered_json(quality->second) : nullptr}};
  if (v2lf) {
    r["planes"] = last.planes;
    r["voxels_binned"] = last.binned;
    r["voxels_split"] = last.voxels_split;
    r["stage_seconds_last"] = {{"binning", last.seconds_binning},
                               {"planes", last.seconds_planes},
                               {"swizzle", last.seconds_swizzle}};
  }
  return r;
}

// One benchmark run: the scene on both renderers, one table per view count.
class VoxelRunner {
 public:
  VoxelRunner(lightfield::LightFieldRenderer& per_view, lightfield::LightFieldRenderer& v2lf,
              const VoxelBenchOptions& options)
      : per_view_(per_view), v2lf_(v2lf), options_(options),
        runs_(options.runs > 0 ? options.runs : v2lf.default_runs()) {}

  nlohmann::ordered_json run() {
    const LoadedScene loaded = load_scene(options_);
    const scene::VoxelScene& scene = loaded.scene.voxels();
    per_view_.set_scene(loaded.scene);
    v2lf_.set_scene(loaded.scene);
    const render::CameraSpec spec = !options_.camera_path.empty() ? render::read_camera_json(options_.camera_path)
                                    : options_.scene_path.empty() ? tabletop_voxel_camera()
                                                                  : voxel::frame_voxel_scene(scene, render::kDefaultFovYDeg);
    nlohmann::ordered_json out = {{"benchmark", "voxels"},
                                  {"backend", v2lf_.name()},
                                  {"device", v2lf_.device()},
                                  {"memory", v2lf_.memory_kind()},
                                  {"scene", loaded.label},
                                  {"voxels", scene.size()},
                                  {"supersampling", scene.supersampling},
                                  {"samples_per_voxel", scene.samples_per_voxel},
                                  {"load_seconds", loaded.load_seconds},
                                  {"runs", runs_},
                                  {"warmup", options_.warmup},
                                  {"size", options_.size},
                                  {"view_cone_deg", options_.view_cone_deg},
                                  {"split_levels", options_.split_levels},
                                  {"plane_lowpass", options_.plane_lowpass},
                                  {"tables", nlohmann::ordered_json::array()}};
    std::printf("lfd bench voxels: %s (%s); median of %d frames after %d warm-up; peak memory: %s; PSNR/SSIM "
                "against the per-view quilt of the same backend\n",
                v2lf_.name().c_str(), v2lf_.device().c_str(), runs_, options_.warmup, v2lf_.memory_kind().c_str());
    for (int views : options_.views)
      out["tables"].push_back(
          run_table(loaded.label, scene, lightfield::plan_views(lightfield::square_views(spec, options_.size, options_.view_cone_deg, views))));
    return out;
  }

 private:
  nlohmann::ordered_json run_table(const std::string& label, const scene::VoxelScene& scene,
                                   const lightfield::ViewPlan& plan) {
    const render::QuiltGeometry& geometry = plan.geometry;
    const int views = geometry.views;
    const display::QuiltGrid grid{plan.layout.cols, plan.layout.rows};
    const render::QuiltLayout& layout = plan.layout;
    // V2LF's default D_shift: the reference camera at the base camera.
    const float d_forward = render::forward_distance(geometry);
    std::printf("\n#### %s: %zu voxels (ss %.2g, K %d), %d views of %dx%d (%dx%d quilt), view cone %.0f deg, "
                "split levels %d, plane low-pass %s\n\n",
                label.c_str(), scene.size(), scene.supersampling, scene.samples_per_voxel, views, options_.size,
                options_.size, layout.width, layout.height, options_.view_cone_deg, options_.split_levels,
                options_.plane_lowpass ? "on" : "off");
    std::printf("| method | binning | median [s] | min-max [s] | FPS | speed-up | planes [GB] | peak [GB] | "
                "PSNR [dB] | SSIM |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    nlohmann::ordered_json table = {{"views", views},
                                    {"grid", {grid.cols, grid.rows}},
                                    {"quilt", {layout.width, layout.height}},
                                    {"rows", nlohmann::ordered_json::array()}};
    const Measured truth = measure(per_view_, geometry, layout, options_.warmup, runs_);
    table["rows"].push_back(print_row("per-view SVR (ground truth)", "-", truth, truth, false, std::nullopt));
    for (const std::string& binning : options_.binnings)
      for (const G2lfConfig& c : g2lf_configs_in(options_.config_sets, "voxel benchmark: config_sets")) {
        if (options_.only_chunks > 0 && c.chunks != options_.only_chunks) continue;
        table["rows"].push_back(v2lf_row(geometry, layout, d_forward, binning, c, truth));
      }
    return table;
  }

  nlohmann::ordered_json v2lf_row(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                  float d_forward, const std::string& binning, const G2lfConfig& c,
                                  const Measured& truth) {
    lightfield::RendererOptions o = v2lf_.options();
    o.planes = render::G2lfOptions{};
    o.planes.binning = render::parse_chunk_binning(binning);
    o.planes.chunks = c.chunks;
    o.planes.plane_scale = c.plane_scale > 0 ? c.plane_scale : equal_density_plane_scale(geometry, d_forward);
    o.planes.filter = c.filter;
    o.planes.precision = c.precision;
    o.planes.adaptive_filter = options_.plane_lowpass;
    o.split_levels = options_.split_levels;
    v2lf_.set_options(o);
    const Measured m = measure(v2lf_, geometry, layout, options_.warmup, runs_);
    nlohmann::ordered_json r =
        print_row(v2lf_label(c), binning, m, truth, true,
                  std::make_pair(render::psnr(m.quilt, truth.quilt), render::ssim(m.quilt, truth.quilt)));
    add_config_fields(r, c, o.planes.plane_scale);
    return r;
  }

  lightfield::LightFieldRenderer& per_view_;
  lightfield::LightFieldRenderer& v2lf_;
  const VoxelBenchOptions& options_;
  const int runs_;
};

}  // namespace

nlohmann::ordered_json run_voxel_benchmark(lightfield::LightFieldRenderer& per_view, lightfield::LightFieldRenderer& v2lf,
                                           const VoxelBenchOptions& options) {
  options.check();
  return VoxelRunner(per_view, v2lf, options).run();
}

}  // namespace lfd::bench
