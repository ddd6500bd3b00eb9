#include "bench/gl_vs_cpu_benchmark.hpp"

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/planes/gl_swizzle.hpp"
#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/quilt_geometry.hpp"
#include "render/scene_generator.hpp"
#include "scene/gaussian_io.hpp"
#include "util/default_display.hpp"
#include "util/stopwatch.hpp"

namespace lfd::bench {

namespace {

std::string describe(const render::G2lfOptions& o) {
  return fmt::format("N={} {} {} P_s={} {}", o.chunks,
                     o.binning == render::ChunkBinning::kMixed ? "mixed" : "quantile",
                     o.filter == render::PlaneFilter::kNearest ? "nearest" : "bilinear",
                     o.plane_scale, o.precision == render::PlanePrecision::kU8 ? "u8" : "f32");
}

}  // namespace

lightfield::ViewRequest strip_of_views(const GlVsCpuScene& s, int views) {
  lightfield::ViewRequest request;
  request.base_camera = s.base;
  request.focal_distance = s.focal_distance;
  request.views = views;
  request.grid = display::QuiltGrid{views, 1};
  return request;
}

GlVsCpuScene gl_vs_cpu_scene_file(const std::string& path, int size) {
  GlVsCpuScene s;
  s.scene = scene::load_gaussian_scene(path);
  s.name = fmt::format("{} ({})", path, s.scene.size());
  const render::CameraSpec spec = render::frame_scene(s.scene);
  s.base = render::camera_from_spec(spec, size, size);
  s.focal_distance = glm::length(spec.look_at - spec.position);
  return s;
}

GlVsCpuScene gl_vs_cpu_tabletop(int gaussians, int size) {
  render::SceneGeneratorOptions generated;
  generated.count = gaussians;
  generated.seed = 5;
  GlVsCpuScene s;
  s.name = fmt::format("generated tabletop ({})", gaussians);
  s.scene = render::generate_scene(generated);
  s.base = render::make_look_at_camera({0, -1, -5}, {0, 0, 0}, {0, -1, 0}, 0.7f, size, size);
  s.focal_distance = 5.1f;
  return s;
}

std::vector<render::G2lfOptions> gl_vs_cpu_configs() {
  using render::ChunkBinning, render::PlaneFilter, render::PlanePrecision;
  auto config = [](int chunks, ChunkBinning binning, PlaneFilter filter, int plane_scale,
                   PlanePrecision precision) {
    render::G2lfOptions o;
    o.chunks = chunks;
    o.binning = binning;
    o.filter = filter;
    o.plane_scale = plane_scale;
    o.precision = precision;
    o.d_shift = -1.0f;
    return o;
  };
  return {config(64, ChunkBinning::kMixed, PlaneFilter::kNearest, 1, PlanePrecision::kU8),
          config(64, ChunkBinning::kQuantile, PlaneFilter::kBilinear, 2, PlanePrecision::kU8),
          config(512, ChunkBinning::kMixed, PlaneFilter::kNearest, 1, PlanePrecision::kU8),
          config(64, ChunkBinning::kMixed, PlaneFilter::kNearest, 1, PlanePrecision::kF32)};
}

std::vector<GlVsCpuRow> run_gl_vs_cpu(const GlVsCpuScene& s, int views, const gpu::GlInfo& info) {
  const lightfield::ViewPlan plan = lightfield::plan_views(strip_of_views(s, views));
  const render::QuiltGeometry& geometry = plan.geometry;
  const render::QuiltLayout& layout = plan.layout;
  const gpu::GlScene scene(s.scene, info);
  gpu::GlG2lfRenderer renderer(scene, info);
  const gpu::Texture quilt = gpu::make_quilt_texture(layout, GL_RGBA32F);
  std::vector<GlVsCpuRow> rows;
  for (const render::G2lfOptions& g2lf : gl_vs_cpu_configs()) {
    gpu::GlG2lfOptions options;
    options.g2lf = g2lf;
    options.gpu_timers = true;  // the frame waits for the GPU: its wall time is the frame's
    Stopwatch stopwatch;
    renderer.render_quilt(geometry, layout, options, {}, quilt);
    const double gl_seconds = stopwatch.seconds();
    stopwatch.restart();
    const ImageF cpu = render::render_quilt_g2lf(s.scene, geometry, layout, g2lf);
    const double cpu_seconds = stopwatch.seconds();
    const gpu::GlG2lfStats& st = renderer.stats();
    GlVsCpuRow r;
    r.scene = s.name;
    r.gaussians = s.scene.size();
    r.views = views;
    r.width = s.base.width;
    r.height = s.base.height;
    r.options = describe(g2lf);
    r.psnr_db = render::psnr(gpu::read_image_top_down(quilt), cpu);
    r.gpu_binning_s = st.seconds_binning;
    r.gpu_planes_s = st.seconds_planes;
    r.gpu_swizzle_s = st.seconds_swizzle;
    r.gl_frame_s = gl_seconds;
    r.cpu_frame_s = cpu_seconds;
    rows.push_back(r);
  }
  return rows;
}

std::string gl_vs_cpu_table(const std::vector<GlVsCpuRow>& rows) {
  std::string t =
      "| scene | views | options | PSNR GL vs CPU dB | GPU binning s | GPU planes s | GPU swizzle s "
      "| GL frame s | CPU frame s |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    t += fmt::format("| {} | {} of {}x{} | {} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n",
                     r.scene, r.views, r.width, r.height, r.options, r.psnr_db, r.gpu_binning_s,
                     r.gpu_planes_s, r.gpu_swizzle_s, r.gl_frame_s, r.cpu_frame_s);
  return t;
}

nlohmann::ordered_json gl_vs_cpu_json(const std::vector<GlVsCpuRow>& rows) {
  nlohmann::ordered_json j = {{"benchmark", "gl-vs-cpu"}, {"rows", nlohmann::ordered_json::array()}};
  for (const auto& r : rows)
    j["rows"].push_back({{"scene", r.scene},
                         {"gaussians", r.gaussians},
                         {"views", r.views},
                         {"size", {r.width, r.height}},
                         {"options", r.options},
                         {"psnr_db", r.psnr_db},
                         {"gpu_seconds_binning", r.gpu_binning_s},
                         {"gpu_seconds_planes", r.gpu_planes_s},
                         {"gpu_seconds_swizzle", r.gpu_swizzle_s},
                         {"gl_frame_seconds", r.gl_frame_s},
                         {"cpu_frame_seconds", r.cpu_frame_s}});
  return j;
}

}  // namespace lfd::bench
