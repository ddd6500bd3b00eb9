#include "bench/direct_baseline_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "bench/timing_stats.hpp"
#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"
#include "interlace/view_masks.hpp"
#include "lightfield/view_plan.hpp"
#include "render/default_camera.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "util/error.hpp"
#include "util/stopwatch.hpp"

namespace lfd::bench {
namespace {

namespace fs = std::filesystem;

// The views the display asks for around the scene's framing (as `lfd bench direct` frames them).
struct Frame {
  display::Calibration calibration;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};

Frame make_frame(const std::string& path, const scene::Scene& scene, int view_height, int views) {
  Frame f;
  f.calibration = display::read_calibration(path);
  lightfield::ViewRequest request = lightfield::display_views_request(f.calibration, view_height);
  if (views > 0) request.views = views;
  const lightfield::ViewPlan v = lightfield::plan_views(request, &scene);
  f.geometry = v.geometry;
  f.layout = v.layout;
  return f;
}

double max_abs_difference(const ImageF& a, const ImageF& b) {
  double worst = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, double(std::abs(a.pixels[i] - b.pixels[i])));
  return worst;
}

nlohmann::ordered_json run_row(lightfield::LightFieldRenderer& sweeping, const SceneSource& source,
                               const scene::Scene& scene, const std::string& calibration_path,
                               int views, const DirectBaselineOptions& options) {
  const Frame f = make_frame(calibration_path, scene, options.view_height, views);
  const display::LensModel lens(f.calibration.display, f.calibration.correction);
  interlace::InterlaceOptions io;
  io.blend = options.blend;
  const interlace::Interlacer interlacer(lens, f.layout, io);
  Stopwatch stopwatch;
  const interlace::ViewMasks masks = interlace::view_masks(interlacer);
  const double mask_seconds = stopwatch.seconds();
  const double fraction_in = masks.fraction_in();

  lightfield::RendererOptions direct = sweeping.options();
  direct.planes.chunks = options.chunks;
  direct.planes.filter = options.direct_filter;
  sweeping.set_options(direct);
  const scene::GaussianScene& gaussians = scene.gaussians();
  std::vector<double> full_s, masked_s, direct_s;
  ImageF full_panel, masked_panel;
  for (int i = 0; i < options.warmup + options.runs; ++i) {
    stopwatch.restart();
    full_panel = interlacer.interlace(render::render_quilt_per_view(gaussians, f.geometry, f.layout));
    const double full = stopwatch.seconds();
    stopwatch.restart();
    masked_panel =
        interlacer.interlace(render::render_quilt_per_view_masked(gaussians, f.geometry, f.layout, masks.masks));
    const double masked = stopwatch.seconds();
    stopwatch.restart();
    sweeping.render_panel(f.geometry, lens, {});
    const double direct_frame = stopwatch.seconds();
    if (i < options.warmup) continue;
    full_s.push_back(full);
    masked_s.push_back(masked);
    direct_s.push_back(direct_frame);
  }
  const TimingStats fs_ = summarize(full_s), ms = summarize(masked_s), ds = summarize(direct_s);
  const double diff = max_abs_difference(full_panel, masked_panel);
  const auto& cal = f.calibration.display;
  const std::string display_name = fs::path(calibration_path).filename().string();
  std::printf("| %s | %s | %dx%d | %d of %dx%d | %.1f %% | %.2f | %.3f | %.3f | %.2fx | %.3f | %.2fx | %.2g |\n",
              source.label().c_str(), display_name.c_str(), cal.screen_w, cal.screen_h, f.geometry.views,
              f.geometry.base.width, f.geometry.base.height, 100.0 * fraction_in, mask_seconds, fs_.median,
              ms.median, fs_.median / ms.median, ds.median, ms.median / ds.median, diff);
  std::fflush(stdout);
  return {{"scene", source.label()},
          {"primitives", scene.size()},
          {"display", display_name},
          {"panel", {cal.screen_w, cal.screen_h}},
          {"views", f.geometry.views},
          {"view_size", {f.geometry.base.width, f.geometry.base.height}},
          {"fraction_masked_in", fraction_in},
          {"mask_seconds", mask_seconds},
          {"per_view_seconds", fs_.to_json()},
          {"per_view_masked_seconds", ms.to_json()},
          {"mask_speedup", fs_.median / ms.median},
          {"direct_frame_seconds", ds.to_json()},
          {"masked_over_direct", ms.median / ds.median},
          {"max_panel_difference", diff}};
}

}  // namespace

void DirectBaselineOptions::check() const {
  const auto fail = [](const std::string& field, const std::string& problem) {
    throw_input_error("direct baseline benchmark: {}: {}", field, problem);
  };
  if (calibrations.empty()) fail("calibrations", "no display");
  if (scenes.empty()) fail("scenes", "no scene");
  if (chunks < 1 || chunks > 4096) fail("chunks", fmt::format("{} is outside 1..4096", chunks));
  if (runs < 1 || runs > 1000) fail("runs", fmt::format("{} is outside 1..1000", runs));
  if (warmup < 0 || warmup > 100) fail("warmup", fmt::format("{} is outside 0..100", warmup));
  if (view_height < 16 || view_height > 4096) fail("view_height", fmt::format("{} is outside 16..4096", view_height));
  if (views.empty()) fail("views", "no view count");
  for (int v : views)
    if (v < 0 || v > 256) fail("views", fmt::format("{} is outside 1..256 (0: the display's)", v));
}

nlohmann::ordered_json run_direct_baseline_benchmark(lightfield::LightFieldRenderer& sweeping,
                                                     const DirectBaselineOptions& options) {
  options.check();
  nlohmann::ordered_json out = {{"benchmark", "direct-baseline"}, {"backend", sweeping.name()},
                                {"device", sweeping.device()},     {"runs", options.runs},
                                {"warmup", options.warmup},        {"chunks", options.chunks},
                                {"blend", interlace::view_blend_name(options.blend)},
                                {"rows", nlohmann::ordered_json::array()}};
  std::printf("lfd bench direct --baseline: per-view direct (each view rasterised by the exact 3DGS pass only "
              "where the panel reads it, then interlaced, %s blending) against the full per-view views and the "
              "direct pass (N_chunk %d, backend %s); per row the median of %d frames of each side after %d "
              "warm-up, the sides alternating; 'max diff': largest |masked - unmasked| over the panel\n\n",
              interlace::view_blend_name(options.blend), options.chunks, sweeping.name().c_str(), options.runs,
              options.warmup);
  std::printf("| scene | display | panel | views | masked in | mask [s] | per view [s] | per view, masked [s] "
              "| mask speed-up | direct frame [s] | masked / direct | max diff |\n");
  std::printf("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const SceneSource& source : options.scenes) {
    if (!source.path.empty() && !fs::exists(source.path)) {
      std::printf("| %s | skipped: not found |||||||||||\n", source.path.c_str());
      continue;
    }
    const scene::Scene scene(source.load_gaussians());
    sweeping.set_scene(scene);
    for (const std::string& calibration : options.calibrations)
      for (int views : options.views)
        out["rows"].push_back(run_row(sweeping, source, scene, calibration, views, options));
  }
  return out;
}

}  // namespace lfd::bench
