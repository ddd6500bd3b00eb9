#include "bench/gpu_frame_benchmark.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/timing_stats.hpp"
#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/planes/gl_swizzle.hpp"
#include "gpu/voxels/gl_v2lf.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "render/quilt_geometry.hpp"
#include "render/per_view_quilt.hpp"
#include "util/default_display.hpp"
#include "voxel/voxel_generator.hpp"
#include "util/stopwatch.hpp"

namespace lfd::bench {
namespace {

// Median wall time of `frame` (which must leave the GPU idle or not: glFinish follows each
// batch) over options.runs batches after options.warmup, per frame.
double median_frame_seconds(const GpuFrameOptions& o, int batch, const std::function<void()>& frame) {
  std::vector<double> per_frame;
  for (int run = 0; run < o.warmup + o.runs; ++run) {
    const Stopwatch stopwatch;
    for (int i = 0; i < batch; ++i) frame();
    glFinish();
    if (run >= o.warmup) per_frame.push_back(stopwatch.seconds() / batch);
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
      const Stopwatch stopwatch;
      for (int i = 0; i < batch; ++i) {
        renderers[v]->render_quilt(geometry, layout, options, {}, quilt);
        const gpu::GlG2lfStats& st = renderers[v]->stats();
        if (run < o.warmup) continue;
        stages[v].binning.push_back(st.seconds_binning);
        stages[v].planes.push_back(st.seconds_planes);
        stages[v].swizzle.push_back(st.seconds_swizzle);
      }
      glFinish();
      if (run >= o.warmup) frames[v].push_back(stopwatch.seconds() / batch);
    }
  std::vector<GpuFrameRow> rows;
  for (size_t v = 0; v < n; ++v) {
    GpuFrameRow row;
    const gpu::GlG2lfStats& st = renderers[v]->stats();
    row.method = fmt::format("G2LF N={}", variants[v].options.g2lf.chunks);
    const char* drawn = st.raster == gpu::RasterPath::kCompute ? "compute" : gpu::plane_raster_name(st.plane_raster);
    row.variant = fmt::format("{}; planes {} {}", variants[v].name, drawn, gpu::plane_format_name(st.plane_format));
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
                         const render::QuiltLayout& layout, gpu::Texture& quilt, gpu::GlPerViewOptions options,
                         const GpuFrameOptions& o, const std::string& variant) {
  options.gpu_timers = true;
  gpu::GlPerViewRenderer renderer(scene, options);
  GpuFrameRow row;
  row.method = "per view";
  row.variant = variant;
  row.runs = o.runs;
  Stages stages;
  std::vector<double> sort;
  row.frame_s = median_frame_seconds(o, options.timer_reads == gpu::TimerReads::kLate ? o.batch : 1, [&] {
    renderer.render_quilt(geometry, layout, {}, quilt);
    const gpu::GlPerViewStats& st = renderer.stats();
    stages.raster.push_back(st.preprocess_s + st.sort_s + st.raster_s);
    sort.push_back(st.sort_s);
  });
  fill_stages(row, stages);
  row.sort_s = summarize(sort).median;
  return row;
}

gpu::GlPerViewOptions per_view_options(gpu::TimerReads reads, GLenum accumulation, int key_bits,
                                       gpu::RasterPath raster = gpu::RasterPath::kHardware) {
  gpu::GlPerViewOptions options;
  options.raster = raster;
  options.depth_key_bits = key_bits;
  options.timer_reads = reads;
  options.accumulation_format = accumulation;
  return options;
}

// Runs o.warmup + o.runs rounds, each timing one frame of every variant in turn (wall time to
// glFinish; `frame(v)` renders variant v and returns its GPU sort seconds): variants interleaved,
// so a machine whose load changes during the run (shared cores) slows them alike.
std::vector<GpuFrameRow> interleaved_rows(const GpuFrameOptions& o, const std::string& method,
                                          const std::vector<std::string>& variants,
                                          const std::function<double(size_t)>& frame) {
  std::vector<std::vector<double>> seconds(variants.size()), sort(variants.size());
  for (int run = 0; run < o.warmup + o.runs; ++run) {
    for (size_t v = 0; v < variants.size(); ++v) {
      const Stopwatch stopwatch;
      const double sort_s = frame(v);
      glFinish();
      if (run < o.warmup) continue;
      seconds[v].push_back(stopwatch.seconds());
      sort[v].push_back(sort_s);
    }
  }
  std::vector<GpuFrameRow> rows;
  for (size_t v = 0; v < variants.size(); ++v) {
    GpuFrameRow row;
    row.method = method;
    row.variant = variants[v] + " (interleaved)";
    row.runs = o.runs;
    row.frame_s = summarize(seconds[v]).median;
    row.sort_s = summarize(sort[v]).median;
    rows.push_back(row);
  }
  return rows;
}

// Sorting what is visible (docs/gpu.md "Sorting what is visible"), side by side: G2LF's binning
// sort over all N against the binned ones only (its sort time in the binning column: keys to
// layers); per view the sort over all N against the visible ones, and float keys against 16
// bits normalised to the visible range.
void sort_rows(const gpu::GlScene& scene, const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
               gpu::Texture& quilt, const GpuFrameOptions& o, const gpu::GlInfo& info, std::vector<GpuFrameRow>& rows) {
  {
    gpu::GlG2lfRenderer renderer(scene, info);
    gpu::GlG2lfOptions options;
    options.g2lf.chunks = o.chunks;
    options.g2lf.d_shift = -1.0f;
    options.gpu_timers = true;
    const std::vector<GpuFrameRow> g2lf = interleaved_rows(
        o, fmt::format("G2LF N={}", o.chunks), {"binning sort over all N", "binning sort over the binned Gaussians"},
        [&](size_t v) {
          options.sort_binned_only = v == 1;
          renderer.render_quilt(geometry, layout, options, {}, quilt);
          return renderer.stats().seconds_binning;
        });
    const size_t binned = renderer.stats().gaussians_in_frustum;
    for (GpuFrameRow row : g2lf) {
      row.binning_s = row.sort_s;  // the binning stage (keys to layers), most of it the sort
      row.sort_s = 0;
      row.variant += fmt::format(", {} of {} binned", binned, scene.size());
      rows.push_back(row);
    }
  }
  struct Variant {
    int bits;
    bool visible_only, normalised;
    const char* what;
  };
  const std::vector<Variant> variants{{24, false, false, "sort all N, 24-bit float keys (3 passes)"},
                                      {24, true, false, "sort the visible, 24-bit float keys (3 passes)"},
                                      {16, true, true, "sort the visible, 16-bit normalised keys (2 passes)"},
                                      {32, false, false, "sort all N, 32-bit float keys (4 passes)"},
                                      {32, true, false, "sort the visible, 32-bit float keys (4 passes)"}};
  std::vector<std::unique_ptr<gpu::GlPerViewRenderer>> renderers;
  std::vector<std::string> names;
  for (const Variant& v : variants) {
    gpu::GlPerViewOptions options = per_view_options(gpu::TimerReads::kWait, GL_RGBA32F, v.bits);
    options.gpu_timers = true;
    options.sort_visible_only = v.visible_only;
    options.normalised_depth_keys = v.normalised;
    renderers.push_back(std::make_unique<gpu::GlPerViewRenderer>(scene, options));
    names.push_back(v.what);
  }
  for (const GpuFrameRow& row : interleaved_rows(o, "per view", names, [&](size_t v) {
         renderers[v]->render_quilt(geometry, layout, {}, quilt);
         return renderers[v]->stats().sort_s;
       }))
    rows.push_back(row);
}

GpuFrameRow v2lf_row(gpu::GlV2lfRenderer& renderer, const render::QuiltGeometry& geometry,
                     const render::QuiltLayout& layout, const gpu::Texture& quilt, const glm::vec3& background,
                     const gpu::GlV2lfOptions& options, const GpuFrameOptions& o, const std::string& variant) {
  GpuFrameRow row;
  row.method = fmt::format("V2LF N={}", options.v2lf.planes.chunks);
  row.variant = variant;
  row.runs = o.runs;
  Stages stages;
  row.frame_s = median_frame_seconds(o, o.batch, [&] {
    renderer.render_quilt(geometry, layout, options, background, quilt);
    const gpu::GlV2lfStats& st = renderer.stats();
    stages.binning.push_back(st.seconds_binning);
    stages.planes.push_back(st.seconds_planes);
    stages.swizzle.push_back(st.seconds_swizzle);
  });
  fill_stages(row, stages);
  return row;
}

// V2LF on the generated voxel tabletop (its default camera, the views' size of the Gaussian
// rows): the voxels binned on the CPU and uploaded every frame (the path before) against binned
// on the GPU (gpu/voxels/gl_voxel_binning.hpp); the same frames otherwise, timers read late, alternated
// per run so both see the same machine load.
void append_v2lf_rows(const GpuFrameOptions& o, const render::Camera& gaussian_base, const gpu::GlInfo& info,
                      std::vector<GpuFrameRow>& rows) {
  voxel::VoxelGeneratorOptions generator;
  generator.detail_level = o.voxel_level;
  const scene::VoxelScene scene = voxel::generate_voxel_scene(generator);
  const render::CameraSpec spec = voxel::frame_voxel_scene(scene);
  lightfield::ViewRequest request;  // the Gaussian rows' views: their size, one row of tiles
  request.camera = spec;
  request.size = display::ViewSize{gaussian_base.width, gaussian_base.height};
  request.views = o.views;
  request.grid = display::QuiltGrid{o.views, 1};
  const lightfield::ViewPlan plan = lightfield::plan_views(request);
  const render::QuiltGeometry& geometry = plan.geometry;
  const render::QuiltLayout& layout = plan.layout;
  const gpu::GlVoxelScene gl_scene(scene, info);
  const gpu::Texture quilt = gpu::make_quilt_texture(layout, GL_RGBA8);
  gpu::GlV2lfOptions options;
  options.v2lf.planes.chunks = o.chunks;
  options.gpu_timers = true;
  options.timer_reads = gpu::TimerReads::kLate;
  const std::string scene_name = fmt::format("level-{} tabletop, {} voxels", o.voxel_level, scene.size());
  std::vector<GpuFrameRow> sides[2];
  GpuFrameOptions one = o;
  one.runs = 1;
  for (int run = 0; run < o.runs; ++run)
    for (const bool on_gpu : {false, true}) {
      gpu::GlV2lfRenderer renderer(gl_scene, info);
      options.gpu_binning = on_gpu;
      one.warmup = o.warmup;
      sides[on_gpu].push_back(v2lf_row(renderer, geometry, layout, quilt, scene.background, options, one,
                                       fmt::format("{}: binning on the {}, {} frames a batch", scene_name,
                                                   on_gpu ? "GPU" : "CPU (uploaded per frame)", o.batch)));
    }
  for (const auto& side : sides) {
    GpuFrameRow row = side.front();
    std::vector<double> frame, binning, planes, swizzle;
    for (const GpuFrameRow& r : side) {
      frame.push_back(r.frame_s);
      binning.push_back(r.binning_s);
      planes.push_back(r.planes_s);
      swizzle.push_back(r.swizzle_s);
    }
    row.frame_s = summarize(frame).median;
    row.binning_s = summarize(binning).median;
    row.planes_s = summarize(planes).median;
    row.swizzle_s = summarize(swizzle).median;
    row.runs = o.runs;
    rows.push_back(row);
  }
}

}  // namespace

std::vector<GpuFrameRow> run_gpu_frame(const GlVsCpuScene& s, const GpuFrameOptions& o, const gpu::GlInfo& info) {
  const lightfield::ViewPlan plan = lightfield::plan_views(strip_of_views(s, o.views));
  const render::QuiltGeometry& geometry = plan.geometry;
  const render::QuiltLayout& layout = plan.layout;
  const gpu::GlScene scene(s.scene, info);
  gpu::Texture quilt = gpu::make_quilt_texture(layout, GL_RGBA8);  // the quilt as displayed
  std::vector<GpuFrameRow> rows;
  if (o.sort_only) {
    sort_rows(scene, geometry, layout, quilt, o, info, rows);
    return rows;
  }
  const auto drawn = [&](gpu::RasterPath path) { return std::ranges::find(o.rasters, path) != o.rasters.end(); };
  const bool hardware = drawn(gpu::RasterPath::kHardware), compute = drawn(gpu::RasterPath::kCompute);
  {
    gpu::GlG2lfOptions options;
    options.g2lf.chunks = o.chunks;
    options.g2lf.d_shift = -1.0f;  // D_shift = D_forward, as gl-vs-cpu
    options.gpu_timers = true;
    std::vector<G2lfVariant> variants;
    if (hardware) variants = g2lf_variants(options, o);
    if (compute) {
      options.raster = gpu::RasterPath::kCompute;
      variants.push_back({"--raster compute, timers waited for", options});
      options.timer_reads = gpu::TimerReads::kLate;
      variants.push_back({fmt::format("--raster compute, timers read late, {} frames a batch", o.batch), options});
    }
    rows = g2lf_rows(scene, info, geometry, layout, quilt, variants, o);
  }
  if (!o.per_view) return rows;  // --no-per-view: the G2LF rows alone
  const int bits = 24;  // the viewer's
  if (compute)  // exact 32-bit depth order: the key options do not apply
    rows.push_back(per_view_row(scene, geometry, layout, quilt,
                                per_view_options(gpu::TimerReads::kWait, GL_RGBA32F, 32, gpu::RasterPath::kCompute), o,
                                "--raster compute, timers waited for (all views in one pass)"));
  if (hardware) {
    const auto row = [&](gpu::TimerReads reads, GLenum accumulation, int key_bits, const std::string& variant) {
      rows.push_back(
          per_view_row(scene, geometry, layout, quilt, per_view_options(reads, accumulation, key_bits), o, variant));
    };
    row(gpu::TimerReads::kWait, GL_RGBA32F, 32, "timers waited for, RGBA32F blending, 32-bit depth keys");
    row(gpu::TimerReads::kWait, GL_RGBA32F, bits,
        fmt::format("timers waited for, RGBA32F blending, {}-bit depth keys", bits));
    row(gpu::TimerReads::kLate, GL_RGBA32F, bits,
        fmt::format("timers read late, {} frames a batch, RGBA32F, {}-bit keys", o.batch, bits));
    row(gpu::TimerReads::kWait, GL_RGBA16F, bits,
        fmt::format("timers waited for, RGBA16F blending, {}-bit keys", bits));
  }
  if (o.voxel_level > 0) append_v2lf_rows(o, s.base, info, rows);
  return rows;
}

std::string gpu_frame_table(const std::vector<GpuFrameRow>& rows) {
  std::string out =
      "| method | variant | frame ms | GPU binning ms | GPU planes ms | GPU swizzle ms | GPU per-view raster ms | GPU per-view sort ms |\n"
      "|---|---|---|---|---|---|---|---|\n";
  for (const GpuFrameRow& r : rows)
    out += fmt::format("| {} | {} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} | {:.1f} |\n", r.method, r.variant,
                       r.frame_s * 1e3, r.binning_s * 1e3, r.planes_s * 1e3, r.swizzle_s * 1e3, r.raster_s * 1e3,
                       r.sort_s * 1e3);
  return out;
}

nlohmann::ordered_json gpu_frame_json(const std::vector<GpuFrameRow>& rows) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const GpuFrameRow& r : rows)
    out.push_back({{"method", r.method}, {"variant", r.variant}, {"runs", r.runs}, {"frame_seconds_median", r.frame_s},
                   {"gpu_seconds_median", {{"binning", r.binning_s}, {"planes", r.planes_s}, {"swizzle", r.swizzle_s},
                                           {"per_view_raster", r.raster_s}, {"per_view_sort", r.sort_s}}}});
  return out;
}

}  // namespace lfd::bench
