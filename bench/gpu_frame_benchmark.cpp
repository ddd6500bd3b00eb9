#include "bench/gpu_frame_benchmark.hpp"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/timing_stats.hpp"
#include "gpu/gl_g2lf.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_scene.hpp"
#include "gpu/gl_swizzle.hpp"
#include "render/quilt_geometry.hpp"
#include "render/per_view_quilt.hpp"
#include "util/default_display.hpp"

namespace lfd::bench {
namespace {

using Clock = std::chrono::steady_clock;

// Median wall time of `frame` (which must leave the GPU idle or not: glFinish follows each
// batch) over options.runs batches after options.warmup, per frame.
double median_frame_seconds(const GpuFrameOptions& o, int batch, const std::function<void()>& frame) {
  std::vector<double> per_frame;
  for (int run = 0; run < o.warmup + o.runs; ++run) {
    const auto t0 = Clock::now();
    for (int i = 0; i < batch; ++i) frame();
    glFinish();
    if (run >= o.warmup) per_frame.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / batch);
  }
  return summarize(per_frame).median;
}

struct Stages {
  std::vector<double> binning, planes, swizzle, raster;
};

void fill_stages(GpuFrameRow& row, const Stages& s) {
  row.binning_s = summarize(s.binning).median;
  row.planes_s = summarize(s.planes).median;
  row.swizzle_s = summarize(s.swizzle).median;
  row.raster_s = summarize(s.raster).median;
}

struct G2lfVariant {
  std::string name;
  gpu::GlG2lfOptions options;
};

// Each variant on a renderer of its own (switching one renderer's planes would time their
// reallocation), the runs interleaved: run r of every variant, then run r + 1, so a load that
// drifts during the benchmark (a shared machine) weighs on every variant alike. The variant's
// name gets the planes as drawn (the raster and format, after any fallback).
std::vector<GpuFrameRow> g2lf_rows(const gpu::GlScene& scene, const gpu::GlInfo& info,
                                   const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                   const gpu::Texture& quilt, const std::vector<G2lfVariant>& variants,
                                   const GpuFrameOptions& o) {
  const size_t n = variants.size();
  std::vector<std::unique_ptr<gpu::GlG2lfRenderer>> renderers;
  for (size_t v = 0; v < n; ++v) renderers.push_back(std::make_unique<gpu::GlG2lfRenderer>(scene, info));
  std::vector<std::vector<double>> frames(n);
  std::vector<Stages> stages(n);
  for (int run = 0; run < o.warmup + o.runs; ++run)
    for (size_t v = 0; v < n; ++v) {
      const gpu::GlG2lfOptions& options = variants[v].options;
      const int batch = options.timer_reads == gpu::TimerReads::kLate ? o.batch : 1;
      const auto t0 = Clock::now();
      for (int i = 0; i < batch; ++i) {
        renderers[v]->render_quilt(geometry, layout, options, {}, quilt);
        const gpu::GlG2lfStats& st = renderers[v]->stats();
        if (run < o.warmup) continue;
        stages[v].binning.push_back(st.seconds_binning);
        stages[v].planes.push_back(st.seconds_planes);
        stages[v].swizzle.push_back(st.seconds_swizzle);
      }
      glFinish();
      if (run >= o.warmup) frames[v].push_back(std::chrono::duration<double>(Clock::now() - t0).count() / batch);
    }
  std::vector<GpuFrameRow> rows;
  for (size_t v = 0; v < n; ++v) {
    GpuFrameRow row;
    const gpu::GlG2lfStats& st = renderers[v]->stats();
    row.method = fmt::format("G2LF N={}", variants[v].options.g2lf.chunks);
    row.variant = fmt::format("{}; planes {} {}", variants[v].name, gpu::plane_raster_name(st.plane_raster),
                              gpu::plane_format_name(st.plane_format));
    row.runs = o.runs;
    row.frame_s = summarize(frames[v]).median;
    fill_stages(row, stages[v]);
    rows.push_back(row);
  }
  return rows;
}

// The variants: swizzle views per invocation; the plane raster (u8 precision: batched RGBA8,
// layered RGBA16F, layered RGBA8); the swizzle's table off and on; bilinear by hand and by the
// texture unit; timers read late.
std::vector<G2lfVariant> g2lf_variants(gpu::GlG2lfOptions options, const GpuFrameOptions& o) {
  std::vector<G2lfVariant> out;
  const gpu::GlG2lfOptions defaults = options;
  for (const int views : o.swizzle_views) {
    options.swizzle_views = views;
    out.push_back({fmt::format("timers waited for, swizzle {} view{}/invocation", views, views > 1 ? "s" : ""), options});
  }
  for (const std::string& planes : o.planes) {
    options = defaults;
    options.plane_raster = planes == "batched" ? gpu::PlaneRaster::kBatched : gpu::PlaneRaster::kLayered;
    if (planes == "layered-rgba8") options.plane_format = gpu::PlaneFormat::kRgba8;
    out.push_back({fmt::format("timers waited for, --planes {}", planes), options});
  }
  for (const bool table : o.swizzle_table) {
    options = defaults;
    options.swizzle_table = table;
    out.push_back({fmt::format("timers waited for, swizzle table {}", table ? "on" : "off"), options});
  }
  for (const bool hardware : o.hardware_bilinear) {
    options = defaults;
    options.g2lf.filter = render::PlaneFilter::kBilinear;
    options.swizzle_hardware_bilinear = hardware;
    out.push_back({fmt::format("timers waited for, bilinear by {}", hardware ? "the texture unit" : "hand"), options});
  }
  options = defaults;
  options.timer_reads = gpu::TimerReads::kLate;
  out.push_back({fmt::format("timers read late, {} frames a batch", o.batch), options});
  return out;
}

GpuFrameRow per_view_row(const gpu::GlScene& scene, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, gpu::Texture& quilt, gpu::TimerReads reads,
                         GLenum accumulation, int key_bits, const GpuFrameOptions& o, const std::string& variant) {
  gpu::GlPerViewOptions options;
  options.depth_key_bits = key_bits;
  options.gpu_timers = true;
  options.timer_reads = reads;
  options.accumulation_format = accumulation;
  gpu::GlPerViewRenderer renderer(scene, options);
  GpuFrameRow row;
  row.method = "per view";
  row.variant = variant;
  row.runs = o.runs;
  Stages stages;
  row.frame_s = median_frame_seconds(o, reads == gpu::TimerReads::kLate ? o.batch : 1, [&] {
    renderer.render_quilt(geometry, layout, {}, quilt);
    const gpu::GlPerViewStats& st = renderer.stats();
    stages.raster.push_back(st.preprocess_s + st.sort_s + st.raster_s);
  });
  fill_stages(row, stages);
  return row;
}

}  // namespace

std::vector<GpuFrameRow> run_gpu_frame(const GlVsCpuScene& s, const GpuFrameOptions& o, const gpu::GlInfo& info) {
  const auto geometry = render::make_quilt_geometry(s.base, s.focal_distance, float(kDefaultViewConeDeg), o.views);
  const auto layout = render::make_quilt_layout(geometry, o.views, 1);
  const gpu::GlScene scene(s.scene, info);
  gpu::Texture quilt = gpu::make_quilt_texture(layout, GL_RGBA8);  // the quilt as displayed
  std::vector<GpuFrameRow> rows;
  {
    gpu::GlG2lfOptions options;
    options.g2lf.chunks = o.chunks;
    options.g2lf.d_shift = -1.0f;  // D_shift = D_forward, as gl-vs-cpu
    options.gpu_timers = true;
    rows = g2lf_rows(scene, info, geometry, layout, quilt, g2lf_variants(options, o), o);
  }
  if (!o.per_view) return rows;
  const int bits = 24;  // the viewer's
  rows.push_back(per_view_row(scene, geometry, layout, quilt, gpu::TimerReads::kWait, GL_RGBA32F, 32, o,
                              "timers waited for, RGBA32F blending, 32-bit depth keys"));
  rows.push_back(per_view_row(scene, geometry, layout, quilt, gpu::TimerReads::kWait, GL_RGBA32F, bits, o,
                              fmt::format("timers waited for, RGBA32F blending, {}-bit depth keys", bits)));
  rows.push_back(per_view_row(scene, geometry, layout, quilt, gpu::TimerReads::kLate, GL_RGBA32F, bits, o,
                              fmt::format("timers read late, {} frames a batch, RGBA32F, {}-bit keys", o.batch, bits)));
  rows.push_back(per_view_row(scene, geometry, layout, quilt, gpu::TimerReads::kWait, GL_RGBA16F, bits, o,
                              fmt::format("timers waited for, RGBA16F blending, {}-bit keys", bits)));
  return rows;
}

std::string gpu_frame_table(const std::vector<GpuFrameRow>& rows) {
  std::string out =
      "| method | variant | frame ms | GPU binning ms | GPU planes ms | GPU swizzle ms | GPU per-view raster ms |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const GpuFrameRow& r : rows)
    out += fmt::format("| {} | {} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} |\n", r.method, r.variant, r.frame_s * 1e3,
                       r.binning_s * 1e3, r.planes_s * 1e3, r.swizzle_s * 1e3, r.raster_s * 1e3);
  return out;
}

nlohmann::ordered_json gpu_frame_json(const std::vector<GpuFrameRow>& rows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const GpuFrameRow& r : rows)
    out.push_back({{"method", r.method}, {"variant", r.variant}, {"runs", r.runs}, {"frame_seconds_median", r.frame_s},
                   {"gpu_seconds_median", {{"binning", r.binning_s}, {"planes", r.planes_s}, {"swizzle", r.swizzle_s},
                                           {"per_view_raster", r.raster_s}}}});
  return out;
}

}  // namespace lfd::bench
