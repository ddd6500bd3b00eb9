#include "bench/direct_benchmark.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "bench/timing_stats.hpp"
#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "interlace/interlacer.hpp"
#include "lightfield/view_plan.hpp"
#include "lightfield/gl_renderer.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "util/error.hpp"
#include "voxel/voxel_generator.hpp"
#include "scene/voxel_io.hpp"
#include "util/stopwatch.hpp"

namespace lfd::bench {
namespace {

namespace fs = std::filesystem;

// One display's frame: the views the display asks for around the scene's framing.
struct Frame {
  std::string display_name;
  display::Calibration calibration;
  display::DisplayQuilt quilt;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};

Frame make_frame(const std::string& path, const scene::Scene& scene, int view_height) {
  Frame f;
  f.display_name = fs::path(path).filename().string();
  f.calibration = display::read_calibration(path);
  const lightfield::ViewPlan v = lightfield::plan_views(lightfield::display_views_request(f.calibration, view_height), &scene);
  f.quilt = *v.display_quilt;
  f.geometry = v.geometry;
  f.layout = v.layout;
  return f;
}

// The quilt path's interlacing on the renderer's backend: the CPU reference interlacer on the
// quilt image, or the interlacing shader on the GL device's quilt texture (its compute pass, as
// the offscreen paths, or the fragment pass a window uses).
class QuiltInterlacer {
 public:
  QuiltInterlacer(lightfield::LightFieldRenderer& renderer, const display::LensModel& lens,
                  const render::QuiltLayout& layout, interlace::ViewBlend blend,
                  gpu::InterlacePass pass = gpu::InterlacePass::kCompute)
      : renderer_(renderer), lens_(lens), layout_(layout) {
    options_.blend = blend;
    gl_ = dynamic_cast<lightfield::GlLightFieldRenderer*>(&renderer);
    if (gl_) {
      gl_interlacer_ = std::make_unique<gpu::GlInterlacer>(lens, layout, options_, pass);
      gl_panel_ = gpu::Texture(renderer.options().gl.quilt_format, lens.calibration().screen_w,
                               lens.calibration().screen_h);
    }
  }
  // The last quilt into the panel; returns the seconds (GL: until the GPU is done).
  double interlace() {
    const Stopwatch stopwatch;
    if (gl_) {
      gl_interlacer_->interlace(gl_->gl_device().quilt(layout_, renderer_.options().gl.quilt_format), gl_panel_);
      glFinish();
    } else {
      panel_ = interlace::interlace(renderer_.read_quilt(), layout_, lens_, options_);
    }
    return stopwatch.seconds();
  }
  ImageF panel() const { return gl_ ? gpu::image_from_texture(gl_panel_) : panel_; }

 private:
  lightfield::LightFieldRenderer& renderer_;
  const display::LensModel& lens_;
  render::QuiltLayout layout_;
  interlace::InterlaceOptions options_;
  lightfield::GlLightFieldRenderer* gl_ = nullptr;
  std::unique_ptr<gpu::GlInterlacer> gl_interlacer_;
  gpu::Texture gl_panel_;
  ImageF panel_;
};

// The continuous reference: every subpixel from the per-view render at `views` views nearest its
// view fraction, looked up as the interlacer looks up a tile (bilinear, the aspect fit), one view
// rendered at a time.
ImageF reference_panel(lightfield::LightFieldRenderer& per_view, const Frame& f, const display::LensModel& lens,
                       int views) {
  const auto& cal = lens.calibration();
  render::QuiltGeometry g = f.geometry;
  g.views = views;
  render::QuiltLayout one;
  one.cols = one.rows = one.views = 1;
  one.width = g.base.width;
  one.height = g.base.height;
  one.aspect = double(g.base.width) / g.base.height;
  const interlace::Interlacer lookup(lens, one);
  std::vector<uint16_t> nearest(size_t(cal.screen_w) * cal.screen_h * 3);
#pragma omp parallel for schedule(dynamic, 16)
  for (int row = 0; row < cal.screen_h; ++row)
    for (int x = 0; x < cal.screen_w; ++x)
      for (int c = 0; c < 3; ++c)
        nearest[(size_t(row) * cal.screen_w + x) * 3 + c] =
            uint16_t(display::LensModel::view_index(lens.subpixel_view_fraction(x, row, c), views));
  ImageF panel(cal.screen_w, cal.screen_h, 3, 0.0f);
  for (int j = 0; j < views; ++j) {
    const ImageF view = per_view.render_view(g, j);
#pragma omp parallel for schedule(dynamic, 16)
    for (int row = 0; row < cal.screen_h; ++row) {
      const double gain = interlace::fringe_gain(cal, row);
      for (int x = 0; x < cal.screen_w; ++x) {
        const interlace::TilePoint t = interlace::tile_point(lens, one.aspect, false, x, row);
        if (!t.inside) continue;
        for (int c = 0; c < 3; ++c)
          if (nearest[(size_t(row) * cal.screen_w + x) * 3 + c] == j)
            panel.at(x, row, c) = float(lookup.sample_tile(view, 0, t.u, t.v, c) * gain);
      }
    }
  }
  return panel;
}

class Runner {
 public:
  Runner(lightfield::LightFieldRenderer& sweeping, lightfield::LightFieldRenderer* per_view,
         const DirectBenchOptions& options)
      : sweeping_(sweeping), per_view_(per_view), options_(options),
        runs_(options.runs > 0 ? options.runs : sweeping.default_runs()) {}

  nlohmann::ordered_json run() {
    nlohmann::ordered_json out = {{"benchmark", "direct"},       {"backend", sweeping_.name()},
                                  {"device", sweeping_.device()}, {"memory", sweeping_.memory_kind()},
                                  {"runs", runs_},                {"warmup", options_.warmup},
                                  {"plane_scale", options_.plane_scale},
                                  {"reference_views", options_.reference_views},
                                  {"direct_filter", options_.direct_filter == render::PlaneFilter::kBilinear
                                                        ? "bilinear" : "nearest"},
                                  {"direct_hardware_bilinear", options_.direct_hardware_bilinear},
                                  {"direct_kernel", render::sample_kernel_name(options_.direct_kernel)},
                                  {"tables", nlohmann::ordered_json::array()}};
    std::printf("lfd bench direct: backend %s (%s); per row the median of %d frames of each side after %d "
                "warm-up, the sides alternating; 'after planes': quilt path = swizzle + interlace, direct = the "
                "direct pass (%s planes%s%s); PSNR against the panel of per-view renders at %d views (nearest view "
                "per subpixel)\n",
                sweeping_.name().c_str(), sweeping_.device().c_str(), runs_, options_.warmup,
                options_.direct_filter == render::PlaneFilter::kBilinear ? "bilinear" : "nearest",
                options_.direct_filter == render::PlaneFilter::kBilinear && sweeping_.name() == "gl"
                    ? (options_.direct_hardware_bilinear ? ", texture unit" : ", by hand")
                    : "",
                sweeping_.name() == "cpu"
                    ? (options_.direct_kernel == render::SampleKernel::kAvx2 ? ", AVX2 kernel" : ", scalar kernel")
                    : "",
                options_.reference_views);
    for (const SceneSource& source : options_.scenes) {
      if (!source.path.empty() && !fs::exists(source.path)) {
        std::printf("\nskipped %s: not found\n", source.path.c_str());
        continue;
      }
      const scene::Scene scene = load(source);
      sweeping_.set_scene(scene);
      if (per_view_) per_view_->set_scene(scene);
      for (const std::string& calibration : options_.calibrations)
        out["tables"].push_back(run_table(source, scene, make_frame(calibration, scene, options_.view_height)));
    }
    return out;
  }

 private:
  scene::Scene load(const SceneSource& source) const {
    if (options_.kind == scene::SceneKind::kVoxels) {
      if (!source.path.empty()) return scene::Scene(scene::load_voxel_scene(source.path));
      voxel::VoxelGeneratorOptions g;
      g.detail_level = int(source.generated);
      return scene::Scene(voxel::generate_voxel_scene(g));
    }
    return scene::Scene(source.load_gaussians());
  }
  std::string label(const SceneSource& source) const {
    if (options_.kind == scene::SceneKind::kVoxels && source.path.empty())
      return fmt::format("generated voxel tabletop (level {})", source.generated);
    return source.label();
  }

  nlohmann::ordered_json run_table(const SceneSource& source, const scene::Scene& scene,
                                   const Frame& f) {
    const display::LensModel lens(f.calibration.display, f.calibration.correction);
    const auto& cal = f.calibration.display;
    std::printf("\n#### %s on %s (%dx%d panel): %zu %s, %d views of %dx%d (%dx%d quilt), view cone %.0f deg\n\n",
                label(source).c_str(), f.display_name.c_str(), cal.screen_w, cal.screen_h, scene.size(),
                scene.primitives(), f.geometry.views, f.geometry.base.width, f.geometry.base.height,
                f.layout.width, f.layout.height, f.quilt.view_cone_deg);
    std::optional<ImageF> reference;
    if (per_view_ && options_.reference_views > 0) {
      const Stopwatch stopwatch;
      reference = reference_panel(*per_view_, f, lens, options_.reference_views);
      std::printf("(reference: %d per-view renders in %.1f s)\n\n", options_.reference_views, stopwatch.seconds());
    }
    std::printf("| N_chunk | swizzle [s] | interlace [s] | after planes: quilt [s] | direct pass [s] | speed-up "
                "| frame: quilt [s] | frame: direct [s] | speed-up | quilt [MB] | PSNR direct [dB] "
                "| PSNR quilt nearest [dB] | PSNR quilt linear [dB] | GL fragment stages: interlace [s] "
                "| direct pass [s] | GL direct pass, plane-major [s] |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    nlohmann::ordered_json table = {{"scene", label(source)},
                                    {"method", options_.kind == scene::SceneKind::kVoxels ? "V2LF" : "G2LF"},
                                    {"primitives", scene.size()},
                                    {"display", f.display_name},
                                    {"panel", {cal.screen_w, cal.screen_h}},
                                    {"views", f.geometry.views},
                                    {"view_size", {f.geometry.base.width, f.geometry.base.height}},
                                    {"quilt", {f.layout.width, f.layout.height}},
                                    {"rows", nlohmann::ordered_json::array()}};
    for (int chunks : options_.chunks) table["rows"].push_back(run_row(f, lens, chunks, reference));
    return table;
  }

  nlohmann::ordered_json run_row(const Frame& f, const display::LensModel& lens, int chunks,
                                 const std::optional<ImageF>& reference) {
    lightfield::RendererOptions o = sweeping_.options();
    o.planes.chunks = chunks;
    o.planes.plane_scale = options_.plane_scale;
    o.gl.gpu_timers = true;  // the stage times (they wait at the end of a frame, as glFinish does)
    sweeping_.set_options(o);
    lightfield::RendererOptions direct = o;
    direct.direct_filter = options_.direct_filter;
    direct.gl.direct_hardware_bilinear = options_.direct_hardware_bilinear;
    direct.direct_kernel = options_.direct_kernel;
    QuiltInterlacer nearest(sweeping_, lens, f.layout, interlace::ViewBlend::kNearest);
    // GL: the fragment stages of the interlacer and the direct pass (what a window draws with),
    // timed in the same rounds as the compute passes the offscreen paths use.
    const bool gl = dynamic_cast<lightfield::GlLightFieldRenderer*>(&sweeping_) != nullptr;
    std::optional<QuiltInterlacer> nearest_fragment;
    if (gl) nearest_fragment.emplace(sweeping_, lens, f.layout, interlace::ViewBlend::kNearest, gpu::InterlacePass::kFragment);
    lightfield::RendererOptions direct_fragment = direct;
    direct_fragment.gl.direct_compute = false;
    lightfield::RendererOptions direct_plane_major = direct;
    direct_plane_major.gl.direct_plane_major = true;
    const bool plane_major = gl && options_.plane_major;
    std::vector<double> swizzle, interlace_s, after_quilt, direct_pass, frame_quilt, frame_direct;
    std::vector<double> interlace_fragment, direct_pass_fragment, direct_pass_plane_major;
    for (int i = 0; i < options_.warmup + runs_; ++i) {
      Stopwatch stopwatch;
      const lightfield::QuiltStats q = sweeping_.render_quilt(f.geometry, f.layout);
      const double il = nearest.interlace();
      const double quilt_frame = stopwatch.seconds();
      const double il_fragment = gl ? nearest_fragment->interlace() : 0.0;
      double direct_fragment_seconds = 0;
      if (gl) {  // first, so the compute pass's panel is the one read back below
        sweeping_.set_options(direct_fragment);
        direct_fragment_seconds = sweeping_.render_panel(f.geometry, lens, {}).seconds_swizzle;
      }
      double plane_major_seconds = 0;
      if (plane_major) {
        sweeping_.set_options(direct_plane_major);
        plane_major_seconds = sweeping_.render_panel(f.geometry, lens, {}).seconds_swizzle;
      }
      sweeping_.set_options(direct);
      stopwatch.restart();
      const lightfield::QuiltStats d = sweeping_.render_panel(f.geometry, lens, {});
      const double direct_frame = stopwatch.seconds();
      sweeping_.set_options(o);
      if (i < options_.warmup) continue;
      if (gl) {
        interlace_fragment.push_back(il_fragment);
        direct_pass_fragment.push_back(direct_fragment_seconds);
      }
      if (plane_major) direct_pass_plane_major.push_back(plane_major_seconds);
      swizzle.push_back(q.seconds_swizzle);
      interlace_s.push_back(il);
      after_quilt.push_back(q.seconds_swizzle + il);
      direct_pass.push_back(d.seconds_swizzle);
      frame_quilt.push_back(quilt_frame);
      frame_direct.push_back(direct_frame);
    }
    const TimingStats sw = summarize(swizzle), il = summarize(interlace_s), aq = summarize(after_quilt),
                      dp = summarize(direct_pass), fq = summarize(frame_quilt), fd = summarize(frame_direct);
    std::optional<TimingStats> il_fragment, dp_fragment, dp_plane_major;
    if (gl) {
      il_fragment = summarize(interlace_fragment);
      dp_fragment = summarize(direct_pass_fragment);
    }
    if (plane_major) dp_plane_major = summarize(direct_pass_plane_major);
    const double quilt_mb = double(f.layout.width) * f.layout.height *
                            (dynamic_cast<lightfield::GlLightFieldRenderer*>(&sweeping_) ? 4.0 : 12.0) / 1e6;
    std::optional<double> psnr_direct, psnr_nearest, psnr_linear;
    if (reference) {
      psnr_direct = render::psnr(sweeping_.read_panel(), *reference);
      sweeping_.render_quilt(f.geometry, f.layout);
      nearest.interlace();
      psnr_nearest = render::psnr(nearest.panel(), *reference);
      QuiltInterlacer linear(sweeping_, lens, f.layout, interlace::ViewBlend::kLinear);
      linear.interlace();
      psnr_linear = render::psnr(linear.panel(), *reference);
    }
    const auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{:.2f}", *v) : std::string("-"); };
    const auto seconds = [](const std::optional<TimingStats>& t) {
      return t ? fmt::format("{:.3f}", t->median) : std::string("-");
    };
    std::printf("| %d | %.3f | %.3f | %.3f | %.3f | %.2fx | %.3f | %.3f | %.2fx | %.0f | %s | %s | %s | %s | %s | %s |\n",
                chunks, sw.median, il.median, aq.median, dp.median, aq.median / dp.median, fq.median, fd.median,
                fq.median / fd.median, quilt_mb, opt(psnr_direct).c_str(), opt(psnr_nearest).c_str(),
                opt(psnr_linear).c_str(), seconds(il_fragment).c_str(), seconds(dp_fragment).c_str(),
                seconds(dp_plane_major).c_str());
    std::fflush(stdout);
    const auto json_opt = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nullptr; };
    return {{"chunks", chunks},
            {"swizzle_seconds", sw.to_json()},
            {"interlace_seconds", il.to_json()},
            {"after_planes_quilt_seconds", aq.to_json()},
            {"direct_pass_seconds", dp.to_json()},
            {"after_planes_speedup", aq.median / dp.median},
            {"frame_quilt_seconds", fq.to_json()},
            {"frame_direct_seconds", fd.to_json()},
            {"frame_speedup", fq.median / fd.median},
            {"quilt_bytes", quilt_mb * 1e6},
            {"psnr_direct_db", json_opt(psnr_direct)},
            {"psnr_quilt_nearest_db", json_opt(psnr_nearest)},
            {"psnr_quilt_linear_db", json_opt(psnr_linear)},
            {"interlace_fragment_seconds", il_fragment ? il_fragment->to_json() : nlohmann::ordered_json(nullptr)},
            {"direct_pass_fragment_seconds", dp_fragment ? dp_fragment->to_json() : nlohmann::ordered_json(nullptr)},
            {"direct_pass_plane_major_seconds",
             dp_plane_major ? dp_plane_major->to_json() : nlohmann::ordered_json(nullptr)}};
  }

  lightfield::LightFieldRenderer& sweeping_;
  lightfield::LightFieldRenderer* per_view_;
  const DirectBenchOptions& options_;
  const int runs_;
};

}  // namespace

void DirectBenchOptions::check() const {
  const auto fail = [](const std::string& field, const std::string& problem) {
    throw_input_error("direct benchmark: {}: {}", field, problem);
  };
  if (calibrations.empty()) fail("calibrations", "no display");
  if (scenes.empty()) fail("scenes", "no scene");
  if (chunks.empty()) fail("chunks", "no plane count");
  for (int c : chunks)
    if (c < 1 || c > 4096) fail("chunks", fmt::format("{} is outside 1..4096", c));
  if (plane_scale < 1 || plane_scale > 8) fail("plane_scale", fmt::format("{} is outside 1..8", plane_scale));
  if (runs < 0 || runs > 1000) fail("runs", fmt::format("{} is outside 0..1000", runs));
  if (warmup < 0 || warmup > 100) fail("warmup", fmt::format("{} is outside 0..100", warmup));
  if (reference_views != 0 && (reference_views < 2 || reference_views > 4096))
    fail("reference_views", fmt::format("{} is outside 2..4096 (0: none)", reference_views));
  if (view_height < 16 || view_height > 4096) fail("view_height", fmt::format("{} is outside 16..4096", view_height));
  if (kind == scene::SceneKind::kVoxels)
    for (const SceneSource& s : scenes)
      if (s.path.empty()) {
        voxel::VoxelGeneratorOptions g;
        g.detail_level = int(s.generated);
        g.check();
      }
}

nlohmann::ordered_json run_direct_benchmark(lightfield::LightFieldRenderer& sweeping,
                                            lightfield::LightFieldRenderer* per_view,
                                            const DirectBenchOptions& options) {
  options.check();
  return Runner(sweeping, per_view, options).run();
}

}  // namespace lfd::bench
