#include "bench/render_benchmark.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "bench/frame_timing.hpp"
#include "bench/render_configs.hpp"
#include "lightfield/view_plan.hpp"
#include "bench/timing_stats.hpp"
#include "display/display_quilt.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "util/error.hpp"
#include "util/stopwatch.hpp"

namespace lfd::bench {
namespace {

namespace fs = std::filesystem;

// A tabletop framed as a person would: 3 units above the ground (y = +1, "up" is -y), 7.5 in
// front of the middle object row, looking down 18 degrees at the objects, which fill the view;
// the ground's near edge is below the view, nothing lies nearer than ~4.9 (D_forward 4.2).
render::CameraSpec tabletop_camera() {
  render::CameraSpec s;
  s.position = glm::vec3(0.0f, -2.0f, -7.5f);
  s.look_at = glm::vec3(0.0f, 0.4f, 0.5f);
  s.up = glm::vec3(0.0f, -1.0f, 0.0f);
  s.fov_y_deg = 40.0f;
  return s;
}

// The rows' quality against the per-view quilt: PSNR, SSIM.
using Quality = std::optional<std::pair<double, double>>;

class Runner {
 public:
  Runner(lightfield::LightFieldRenderer& per_view, lightfield::LightFieldRenderer& g2lf,
         const RenderBenchOptions& options)
      : per_view_(per_view), g2lf_(g2lf), options_(options),
        runs_(options.runs > 0 ? options.runs : g2lf.default_runs()),
        png_dir_(fs::temp_directory_path() / fmt::format("lfd_bench_render_{}", getpid())) {}
  ~Runner() {
    std::error_code ec;
    fs::remove_all(png_dir_, ec);
  }

  nlohmann::ordered_json run() {
    nlohmann::ordered_json out = {{"benchmark", "render"},
                                  {"backend", g2lf_.name()},
                                  {"device", g2lf_.device()},
                                  {"memory", g2lf_.memory_kind()},
                                  {"runs", runs_},
                                  {"warmup", options_.warmup},
                                  {"png_runs", std::min(options_.png_runs, runs_)},
                                  {"size", {options_.size.width, options_.size.height}},
                                  {"view_cone_deg", options_.view_cone_deg},
                                  {"shift_fraction", options_.shift_fraction},
                                  {"tables", nlohmann::ordered_json::array()}};
    std::printf("lfd bench render: backend %s (%s); median of %d frames after %d warm-up; "
                "CPU: process CPU seconds per frame (all threads); '+PNG': the first %d also read "
                "back, converted to 8 bits and written as PNG; peak memory: %s\n",
                g2lf_.name().c_str(), g2lf_.device().c_str(), runs_, options_.warmup,
                std::min(options_.png_runs, runs_), g2lf_.memory_kind().c_str());
    for (const SceneSource& source : options_.scenes) {
      const Stopwatch stopwatch;
      const scene::Scene scene(source.path.empty() ? generated_scene(source.generated)
                                                                  : scene::load_gaussian_scene(source.path));
      const double load_seconds = stopwatch.seconds();
      per_view_.set_scene(scene);
      g2lf_.set_scene(scene);
      for (int views : options_.views)
        out["tables"].push_back(run_table(source, scene.gaussians(), load_seconds, views));
    }
    return out;
  }

 private:
  static scene::GaussianScene generated_scene(size_t gaussians) {
    render::SceneGeneratorOptions g;
    g.count = gaussians;
    return render::generate_scene(g);
  }

  FrameTimings measure(lightfield::LightFieldRenderer& renderer, const render::QuiltGeometry& geometry,
                       const render::QuiltLayout& layout) {
    return time_frames(renderer, geometry, layout,
                       {.warmup = options_.warmup, .runs = runs_, .png_runs = options_.png_runs,
                        .png_path = png_dir_ / "quilt.png"});
  }

  // One table's quilt: the views of `views` cameras around the scene's framing.
  struct TableSetup {
    render::QuiltGeometry geometry;
    display::QuiltGrid grid;
    render::QuiltLayout layout;
    float d_forward = 0, d_shift = 0;
    std::string label;
  };

  TableSetup setup_table(const SceneSource& source, const scene::GaussianScene& scene, int views) const {
    const bool tabletop = source.path.empty() && options_.tabletop_camera;
    const render::CameraSpec spec = tabletop ? tabletop_camera() : render::frame_scene(scene);
    const lightfield::ViewPlan plan =
        lightfield::plan_views(lightfield::benchmark_views(spec, options_.size, options_.view_cone_deg, views));
    TableSetup t;
    t.geometry = plan.geometry;
    t.grid = {plan.layout.cols, plan.layout.rows};
    t.layout = plan.layout;
    t.d_forward = render::forward_distance(t.geometry);
    t.d_shift = options_.shift_fraction * t.d_forward;
    t.label = source.label() + (tabletop ? ", tabletop camera" : "");
    return t;
  }

  void print_table_head(const SceneSource& source, const scene::GaussianScene& scene, double load_seconds,
                        const TableSetup& t) const {
    std::printf("\n#### %s: %s Gaussians, %d views of %dx%d (%dx%d quilt), view cone %.0f deg, "
                "D_focal %.2f, D_shift %.2f (D_forward %.2f)%s\n\n",
                t.label.c_str(), fmt::format("{}", scene.size()).c_str(), t.geometry.views, options_.size.width,
                options_.size.height, t.layout.width, t.layout.height, options_.view_cone_deg,
                t.geometry.focal_distance, t.d_shift, t.d_forward,
                source.path.empty() ? "" : fmt::format(", loaded in {:.2f} s", load_seconds).c_str());
    std::printf("| method | binning | median [s] | min-max [s] | MAD [s] | CPU [s] | FPS | speed-up "
                "| +PNG [s] | speed-up +PNG | planes [GB] | peak [GB] | PSNR [dB] | SSIM |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  }

  nlohmann::ordered_json run_table(const SceneSource& source, const scene::GaussianScene& scene,
                                   double load_seconds, int views) {
    const TableSetup t = setup_table(source, scene, views);
    print_table_head(source, scene, load_seconds, t);
    nlohmann::ordered_json table = {{"scene", t.label},
                                    {"gaussians", scene.size()},
                                    {"load_seconds", load_seconds},
                                    {"views", views},
                                    {"grid", {t.grid.cols, t.grid.rows}},
                                    {"quilt", {t.layout.width, t.layout.height}},
                                    {"focal_distance", t.geometry.focal_distance},
                                    {"d_forward", t.d_forward},
                                    {"d_shift", t.d_shift},
                                    {"rows", nlohmann::ordered_json::array()}};
    std::optional<FrameTimings> per_view;
    ImageF truth;
    if (options_.per_view) {
      per_view = measure(per_view_, t.geometry, t.layout);
      truth = per_view_.take_quilt();
      table["rows"].push_back(row("per-view 3DGS (ground truth)", "-", *per_view, per_view, 0, false, std::nullopt));
    }
    for (const std::string& binning : options_.binnings)
      for (const G2lfConfig& c : g2lf_configs_in(options_.config_sets, "render benchmark: config_sets")) {
        if (!options_.only_chunks.empty() &&
            std::find(options_.only_chunks.begin(), options_.only_chunks.end(), c.chunks) == options_.only_chunks.end())
          continue;
        if (options_.only_plane_scale > 0 && c.plane_scale != options_.only_plane_scale) continue;
        table["rows"].push_back(g2lf_row(t, binning, c, per_view, truth));
      }
    return table;
  }

  // One G2LF configuration timed, compared with the per-view quilt and printed.
  nlohmann::ordered_json g2lf_row(const TableSetup& t, const std::string& binning, const G2lfConfig& c,
                                  const std::optional<FrameTimings>& per_view, const ImageF& truth) {
    lightfield::RendererOptions o = g2lf_.options();
    o.planes = render::G2lfOptions{};
    o.planes.binning = render::parse_chunk_binning(binning);
    o.planes.chunks = c.chunks;
    o.planes.plane_scale = c.plane_scale > 0 ? c.plane_scale : equal_density_plane_scale(t.geometry, t.d_shift);
    o.planes.filter = c.filter;
    o.planes.precision = c.precision;
    o.planes.d_shift = t.d_shift;
    g2lf_.set_options(o);
    const FrameTimings m = measure(g2lf_, t.geometry, t.layout);
    Quality quality;
    if (per_view) {
      const ImageF& quilt = g2lf_.read_quilt();
      quality = std::make_pair(render::psnr(quilt, truth), render::ssim(quilt, truth));
    }
    nlohmann::ordered_json r = row(config_label(c, o.planes.plane_scale), binning, m, per_view,
                                   m.stats.empty() ? 0 : m.stats.back().plane_bytes, true, quality);
    add_config_fields(r, c, o.planes.plane_scale);
    return r;
  }

  // Prints one table row and returns it as JSON (`g2lf`: with the planes' figures).
  nlohmann::ordered_json row(const std::string& method, const std::string& binning, const FrameTimings& m,
                             const std::optional<FrameTimings>& per_view, size_t plane_bytes, bool g2lf,
                             const Quality& quality) {
    const auto speedup = [&](const TimingStats& mine, const TimingStats& theirs) -> std::optional<double> {
      if (!per_view || mine.median <= 0.0 || theirs.median <= 0.0) return std::nullopt;
      return theirs.median / mine.median;
    };
    const std::optional<double> s = per_view ? speedup(m.render, per_view->render) : std::nullopt;
    const std::optional<double> s_png = per_view ? speedup(m.with_png, per_view->with_png) : std::nullopt;
    const auto opt = [](const std::optional<double>& v, const char* f) {
      return v ? fmt::format(fmt::runtime(f), *v) : std::string("-");
    };
    const bool has_png = !m.with_png.samples.empty();
    std::printf("| %s | %s | %.3f | %.3f-%.3f | %.3f | %.3f | %.2f | %s | %s | %s | %s | %.3f | %s | %s |\n",
                method.c_str(), binning.c_str(), m.render.median, m.render.min, m.render.max,
                m.render.mad, m.cpu.median, 1.0 / m.render.median, opt(s, "{:.1f}x").c_str(),
                has_png ? fmt::format("{:.3f}", m.with_png.median).c_str() : "-",
                opt(s_png, "{:.1f}x").c_str(),
                plane_bytes ? fmt::format("{:.3f}", double(plane_bytes) / 1e9).c_str() : "-",
                double(m.peak_bytes) / 1e9,
                quality ? fmt::format("{:.2f}", quality->first).c_str() : "-",
                quality ? fmt::format("{:.4f}", quality->second).c_str() : "-");
    std::fflush(stdout);
    nlohmann::ordered_json r = {{"method", method},
                                {"binning", binning},
                                {"seconds", m.render.to_json()},
                                {"fps", 1.0 / m.render.median},
                                {"speedup", s ? nlohmann::ordered_json(*s) : nullptr},
                                {"seconds_with_png", has_png ? m.with_png.to_json() : nullptr},
                                {"speedup_with_png", s_png ? nlohmann::ordered_json(*s_png) : nullptr},
                                {"cpu_seconds", m.cpu.to_json()},
                                {"peak_bytes", m.peak_bytes},
                                {"plane_bytes", plane_bytes},
                                {"psnr_db", quality ? nlohmann::ordered_json(quality->first) : nullptr},
                                {"ssim", quality ? nlohmann::ordered_json(quality->second) : nullptr}};
    if (g2lf && !m.stats.empty()) add_plane_figures(r, m.stats);
    return r;
  }

  // The planes of the last frame and the median stage times.
  static void add_plane_figures(nlohmann::ordered_json& r, const std::vector<lightfield::QuiltStats>& stats) {
    std::vector<double> binning_s, planes_s, swizzle_s;
    for (const auto& st : stats) {
      binning_s.push_back(st.seconds_binning);
      planes_s.push_back(st.seconds_planes);
      swizzle_s.push_back(st.seconds_swizzle);
    }
    r["planes"] = stats.back().planes;
    r["gaussians_in_frustum"] = stats.back().binned;
    r["stage_seconds_median"] = {{"binning", summarize(binning_s).median},
                                 {"planes", summarize(planes_s).median},
                                 {"swizzle", summarize(swizzle_s).median}};
  }

  lightfield::LightFieldRenderer& per_view_;
  lightfield::LightFieldRenderer& g2lf_;
  const RenderBenchOptions& options_;
  const int runs_;
  const fs::path png_dir_;
};

}  // namespace

scene::GaussianScene SceneSource::load_gaussians() const {
  if (!path.empty()) return scene::load_gaussian_scene(path);
  render::SceneGeneratorOptions g;
  g.count = generated;
  return render::generate_scene(g);
}

std::string SceneSource::label() const {
  if (!path.empty()) return fs::path(path).filename().string();
  return fmt::format("generated tabletop ({})", generated);
}

void RenderBenchOptions::check() const {
  const auto fail = [](const std::string& field, const std::string& problem) {
    throw_input_error("render benchmark: {}: {}", field, problem);
  };
  if (scenes.empty()) fail("scenes", "no scene to render");
  for (const SceneSource& s : scenes)
    if (s.path.empty() && (s.generated < 1 || s.generated > 100000000))
      fail("scenes", fmt::format("a generated scene of {} Gaussians is outside 1..100000000", s.generated));
  if (views.empty()) fail("views", "no view count");
  for (int v : views)
    if (v < 1 || v > 256) fail("views", fmt::format("{} is outside 1..256", v));
  if (size.width < 16 || size.width > 4096 || size.height < 16 || size.height > 4096)
    fail("size", fmt::format("{}x{} has a side outside 16..4096", size.width, size.height));
  for (int n : only_chunks)
    if (n < 1 || n > 2048) fail("only_chunks", fmt::format("{} is outside 1..2048", n));
  if (only_plane_scale < 0 || only_plane_scale > 8)
    fail("only_plane_scale", fmt::format("{} is outside 0..8", only_plane_scale));
  if (!(view_cone_deg > 0.0f && view_cone_deg < 170.0f))
    fail("view_cone_deg", fmt::format("{} is outside (0, 170)", view_cone_deg));
  if (!(shift_fraction >= 0.0f && shift_fraction <= 1.0f))
    fail("shift_fraction", fmt::format("{} is outside 0..1", shift_fraction));
  for (const std::string& b : binnings) render::parse_chunk_binning(b);
  g2lf_configs_in(config_sets, "render benchmark: config_sets");
  if (runs < 0 || runs > 1000) fail("runs", fmt::format("{} is outside 0..1000", runs));
  if (warmup < 0 || warmup > 100) fail("warmup", fmt::format("{} is outside 0..100", warmup));
  if (png_runs < 0) fail("png_runs", "must not be negative");
}

nlohmann::ordered_json run_render_benchmark(lightfield::LightFieldRenderer& per_view,
                                            lightfield::LightFieldRenderer& g2lf, const RenderBenchOptions& options) {
  options.check();
  return Runner(per_view, g2lf, options).run();
}

}  // namespace lfd::bench
