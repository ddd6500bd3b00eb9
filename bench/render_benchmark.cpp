#include "bench/render_benchmark.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>

#include <fmt/format.h>

#include "bench/render_configs.hpp"
#include "bench/timing_stats.hpp"
#include "display/display_quilt.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "render/scene_io.hpp"
#include "util/error.hpp"

namespace lfd::bench {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// User + system time of all threads: on a shared machine it tells the work done, which wall
// time does not when other jobs take the cores.
double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

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

// One configuration's measurements.
struct Measured {
  TimingStats render;     // render-only frame time
  TimingStats with_png;   // frame + read-back + 8-bit conversion + PNG write
  TimingStats cpu;        // process CPU seconds per frame
  size_t peak_bytes = 0;
  std::vector<render::G2lfStats> g2lf;  // per timed frame (G2LF only)
};

class Runner {
 public:
  Runner(QuiltRenderer& renderer, const RenderBenchOptions& options)
      : renderer_(renderer), options_(options),
        runs_(options.runs > 0 ? options.runs : renderer.default_runs()),
        png_dir_(fs::temp_directory_path() / fmt::format("lfd_bench_render_{}", getpid())) {}
  ~Runner() {
    std::error_code ec;
    fs::remove_all(png_dir_, ec);
  }

  nlohmann::ordered_json run() {
    nlohmann::ordered_json out = {{"benchmark", "render"},
                                  {"backend", renderer_.name()},
                                  {"device", renderer_.device()},
                                  {"memory", renderer_.memory_kind()},
                                  {"runs", runs_},
                                  {"warmup", options_.warmup},
                                  {"png_runs", std::min(options_.png_runs, runs_)},
                                  {"size", options_.size},
                                  {"view_cone_deg", options_.view_cone_deg},
                                  {"shift_fraction", options_.shift_fraction},
                                  {"tables", nlohmann::ordered_json::array()}};
    std::printf("lfd bench render: backend %s (%s); median of %d frames after %d warm-up; "
                "CPU: process CPU seconds per frame (all threads); '+PNG': the first %d also read "
                "back, converted to 8 bits and written as PNG; peak memory: %s\n",
                renderer_.name().c_str(), renderer_.device().c_str(), runs_, options_.warmup,
                std::min(options_.png_runs, runs_), renderer_.memory_kind().c_str());
    for (const SceneSource& source : options_.scenes) {
      const auto t0 = Clock::now();
      render::GaussianScene scene;
      if (!source.path.empty()) {
        scene = render::load_scene(source.path);
      } else {
        render::SceneGeneratorOptions g;
        g.count = source.generated;
        scene = render::generate_scene(g);
      }
      const double load_seconds = seconds_since(t0);
      renderer_.set_scene(scene);
      for (int views : options_.views)
        out["tables"].push_back(run_table(source, scene, load_seconds, views));
    }
    return out;
  }

 private:
  // Warm-up, then the timed frames of `frame`; the first png_runs of them are written as PNG.
  Measured measure(const std::function<void()>& frame, bool g2lf) {
    Measured m;
    renderer_.reset_peak_memory();
    for (int w = 0; w < options_.warmup; ++w) frame();
    std::vector<double> render, with_png, cpu;
    for (int r = 0; r < runs_; ++r) {
      const double c0 = process_cpu_seconds();
      const auto t0 = Clock::now();
      frame();
      const double t = seconds_since(t0);
      render.push_back(t);
      cpu.push_back(process_cpu_seconds() - c0);
      if (g2lf) m.g2lf.push_back(last_g2lf_);
      if (r < options_.png_runs) {
        const auto t1 = Clock::now();
        write_png(png_dir_ / "quilt.png", to_uint8(renderer_.read_quilt()));
        with_png.push_back(t + seconds_since(t1));
      }
    }
    m.peak_bytes = renderer_.peak_memory_bytes();
    m.render = summarize(render);
    m.with_png = summarize(with_png);
    m.cpu = summarize(cpu);
    return m;
  }

  nlohmann::ordered_json run_table(const SceneSource& source, const render::GaussianScene& scene,
                                   double load_seconds, int views) {
    const bool generated = source.path.empty();
    const render::CameraSpec spec = generated && options_.tabletop_camera
                                        ? tabletop_camera()
                                        : render::frame_scene(scene);
    const render::Camera base = render::camera_from_spec(spec, options_.size, options_.size);
    const render::QuiltGeometry geometry = render::make_quilt_geometry(
        base, glm::length(spec.look_at - spec.position), options_.view_cone_deg, views);
    const display::QuiltGrid grid = display::quilt_grid_for_views(views, 1.0);
    const render::QuiltLayout layout = render::make_quilt_layout(geometry, grid.cols, grid.rows);
    const float d_forward = render::make_reference_camera(geometry, 0.0f, 1).d_forward;
    const float d_shift = options_.shift_fraction * d_forward;
    const std::string label = source.label() + (generated && options_.tabletop_camera ? ", tabletop camera" : "");

    std::printf("\n#### %s: %s Gaussians, %d views of %dx%d (%dx%d quilt), view cone %.0f deg, "
                "D_focal %.2f, D_shift %.2f (D_forward %.2f)%s\n\n",
                label.c_str(), fmt::format("{}", scene.size()).c_str(), views, options_.size,
                options_.size, layout.width, layout.height, options_.view_cone_deg,
                geometry.focal_distance, d_shift, d_forward,
                source.path.empty() ? "" : fmt::format(", loaded in {:.2f} s", load_seconds).c_str());
    std::printf("| method | binning | median [s] | min-max [s] | MAD [s] | CPU [s] | FPS | speed-up "
                "| +PNG [s] | speed-up +PNG | planes [GB] | peak [GB] | PSNR [dB] | SSIM |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");

    nlohmann::ordered_json table = {{"scene", label},
                                    {"gaussians", scene.size()},
                                    {"load_seconds", load_seconds},
                                    {"views", views},
                                    {"grid", {grid.cols, grid.rows}},
                                    {"quilt", {layout.width, layout.height}},
                                    {"focal_distance", geometry.focal_distance},
                                    {"d_forward", d_forward},
                                    {"d_shift", d_shift},
                                    {"rows", nlohmann::ordered_json::array()}};
    std::optional<Measured> per_view;
    ImageF truth;
    if (options_.per_view) {
      per_view = measure([&] { renderer_.render_per_view(geometry, layout); }, false);
      truth = renderer_.read_quilt();
      table["rows"].push_back(row("per-view 3DGS (ground truth)", "-", *per_view, per_view, 0, {},
                                  std::nullopt));
    }

    std::vector<G2lfConfig> configs = g2lf_configs_in(options_.config_sets, "render benchmark: config_sets");
    for (const std::string& binning : options_.binnings)
      for (const G2lfConfig& c : configs) {
        if (options_.only_chunks > 0 && c.chunks != options_.only_chunks) continue;
        render::G2lfOptions o;
        o.binning = render::parse_chunk_binning(binning);
        o.chunks = c.chunks;
        o.plane_scale = c.plane_scale > 0 ? c.plane_scale : equal_density_plane_scale(geometry, d_shift);
        o.filter = c.filter;
        o.precision = c.precision;
        o.d_shift = d_shift;
        const Measured m = measure(
            [&] { last_g2lf_ = renderer_.render_g2lf(geometry, layout, o); }, true);
        std::optional<std::pair<double, double>> quality;
        if (per_view) {
          const ImageF& quilt = renderer_.read_quilt();
          quality = std::make_pair(render::psnr(quilt, truth), render::ssim(quilt, truth));
        }
        nlohmann::ordered_json r = row(config_label(c, o.plane_scale), binning, m, per_view,
                                       m.g2lf.empty() ? 0 : m.g2lf.back().plane_bytes, m.g2lf, quality);
        r["config_set"] = c.set;
        r["chunks"] = c.chunks;
        r["plane_scale"] = o.plane_scale;
        r["filter"] = c.filter == render::PlaneFilter::kBilinear ? "bilinear" : "nearest";
        r["precision"] = c.precision == render::PlanePrecision::kF32 ? "f32" : "u8";
        table["rows"].push_back(std::move(r));
      }
    return table;
  }

  // Prints one table row and returns it as JSON.
  nlohmann::ordered_json row(const std::string& method, const std::string& binning, const Measured& m,
                             const std::optional<Measured>& per_view, size_t plane_bytes,
                             const std::vector<render::G2lfStats>& g2lf,
                             const std::optional<std::pair<double, double>>& quality) {
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
    if (!g2lf.empty()) {
      std::vector<double> binning_s, planes_s, swizzle_s;
      for (const auto& st : g2lf) {
        binning_s.push_back(st.seconds_binning);
        planes_s.push_back(st.seconds_planes);
        swizzle_s.push_back(st.seconds_swizzle);
      }
      r["planes"] = g2lf.back().planes;
      r["gaussians_in_frustum"] = g2lf.back().gaussians_in_frustum;
      r["stage_seconds_median"] = {{"binning", summarize(binning_s).median},
                                   {"planes", summarize(planes_s).median},
                                   {"swizzle", summarize(swizzle_s).median}};
    }
    return r;
  }

  QuiltRenderer& renderer_;
  const RenderBenchOptions& options_;
  const int runs_;
  const fs::path png_dir_;
  render::G2lfStats last_g2lf_;
};

}  // namespace

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
  if (size < 16 || size > 4096) fail("size", fmt::format("{} is outside 16..4096", size));
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

nlohmann::ordered_json run_render_benchmark(QuiltRenderer& renderer,
                                            const RenderBenchOptions& options) {
  options.check();
  return Runner(renderer, options).run();
}

}  // namespace lfd::bench
