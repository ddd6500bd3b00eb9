#include "gpu/splats/gl_g2lf.hpp"

#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/gl/gl_quilt_target.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

double mib(double bytes) { return bytes / 1048576.0; }

int batch_layers_for(const GlG2lfOptions& options, const render::QuiltGeometry& geometry) {
  if (options.plane_raster == PlaneRaster::kLayered || options.raster == RasterPath::kCompute) return 0;
  const int s = options.g2lf.plane_scale;
  return plane_batch_layers(options.format(), options.g2lf.chunks, geometry.base.width * s,
                            geometry.base.height * s, options.accumulation_budget_bytes);
}

// The budget of `options` (memory_budget_bytes, else the driver's free bytes if known) and how
// it was found, for the refusal's message.
std::optional<double> budget_bytes(const GlG2lfOptions& options, std::optional<long long> free_bytes,
                                   std::string* what = nullptr) {
  if (options.memory_budget_bytes > 0) {
    if (what) *what = fmt::format("the memory budget is {:.1f} MiB", mib(double(options.memory_budget_bytes)));
    return double(options.memory_budget_bytes);
  }
  if (!free_bytes) return std::nullopt;
  if (what) *what = fmt::format("this GPU has {:.1f} MiB free", mib(double(*free_bytes)));
  return double(*free_bytes);
}

double g2lf_bytes(const GlG2lfOptions& options, const render::QuiltGeometry& geometry, size_t gaussians) {
  return double(g2lf_plane_array_bytes(options, geometry)) + double(g2lf_other_bytes(options, geometry, gaussians));
}

}  // namespace

size_t g2lf_plane_array_bytes(const GlG2lfOptions& options, const render::QuiltGeometry& geometry) {
  const int s = options.g2lf.plane_scale;
  return plane_texture_bytes(options.format(), options.g2lf.chunks, geometry.base.width * s,
                             geometry.base.height * s) +
         plane_table_bytes(options.g2lf.chunks);
}

size_t g2lf_other_bytes(const GlG2lfOptions& options, const render::QuiltGeometry& geometry, size_t gaussians) {
  const int s = options.g2lf.plane_scale;
  const int wp = geometry.base.width * s, hp = geometry.base.height * s;
  // records (64), keys, values, their sort copies, layers (4 each).
  const size_t binning = gaussians * (sizeof(SplatRecord) + 5 * sizeof(uint32_t));
  if (options.raster != RasterPath::kCompute)
    return binning + plane_raster_bytes(options.format(), batch_layers_for(options, geometry), wp, hp, gaussians);
  // The compute path's key buffers (docs/gpu.md "Memory and passes"): the keys are known only
  // after a frame's scan, so they are counted at kComputePlaneKeysPerGaussian a Gaussian.
  const size_t tiles = size_t((wp + render::kTileSize - 1) / render::kTileSize) *
                       size_t((hp + render::kTileSize - 1) / render::kTileSize);
  return binning + GlSplatTileRaster::plane_path_bytes(gaussians, tiles * size_t(options.g2lf.chunks),
                                                  gaussians * kComputePlaneKeysPerGaussian);
}

void check_g2lf_fits(const GlG2lfOptions& options, const render::QuiltGeometry& geometry,
                     size_t gaussians, const GlInfo& info, std::optional<long long> free_bytes) {
  const render::G2lfOptions& o = options.g2lf;
  const int wp = geometry.base.width * o.plane_scale, hp = geometry.base.height * o.plane_scale;
  if (info.max_array_layers > 0 && o.chunks > info.max_array_layers)
    throw_input_error("G2LF on the GPU: --chunks {} is more planes than this GPU's {} texture array "
                      "layers (GL_MAX_ARRAY_TEXTURE_LAYERS); use --chunks {} or fewer",
                      o.chunks, info.max_array_layers, info.max_array_layers);
  if (info.max_texture_size > 0 && std::max(wp, hp) > info.max_texture_size)
    throw_input_error("G2LF on the GPU: planes of {}x{} (--plane-scale {} x {}x{}) exceed this GPU's "
                      "texture size {}; lower --plane-scale",
                      wp, hp, o.plane_scale, geometry.base.width, geometry.base.height, info.max_texture_size);
  const double planes = double(g2lf_plane_array_bytes(options, geometry));
  const double buffers = double(g2lf_other_bytes(options, geometry, gaussians));
  std::string what;
  const std::optional<double> budget = budget_bytes(options, free_bytes, &what);
  if (budget && planes + buffers > *budget)
    throw_input_error("G2LF on the GPU needs {:.1f} MiB ({} planes of {}x{} {}: {:.1f} MiB, "
                      "buffers: {:.1f} MiB) but {}; lower --chunks, --plane-scale or "
                      "--precision",
                      mib(planes + buffers), o.chunks, wp, hp, plane_format_name(options.format()),
                      mib(planes), mib(buffers), what);
}

GlG2lfOptions g2lf_fitting_options(const GlG2lfOptions& options, const render::QuiltGeometry& geometry,
                                   size_t gaussians, std::optional<long long> free_bytes) {
  GlG2lfOptions fitting = options;
  const std::optional<double> budget = budget_bytes(options, free_bytes);
  const bool u8_as_rgba16f = !options.plane_format && options.g2lf.precision == render::PlanePrecision::kU8 &&
                             options.plane_raster == PlaneRaster::kLayered && options.raster != RasterPath::kCompute;
  if (u8_as_rgba16f && budget && g2lf_bytes(options, geometry, gaussians) > *budget)
    fitting.plane_raster = PlaneRaster::kBatched;  // RGBA8 planes: half the plane bytes
  return fitting;
}

GlG2lfRenderer::GlG2lfRenderer(const GlScene& scene, const GlInfo& info) : scene_(scene), info_(info) {}

void GlG2lfRenderer::ensure_planes(const GlG2lfOptions& requested, const render::QuiltGeometry& geometry) {
  const render::G2lfOptions& o = requested.g2lf;
  const int wp = geometry.base.width * o.plane_scale, hp = geometry.base.height * o.plane_scale;
  // A request as the last frame's keeps its planes as drawn then (the fallback included): no
  // driver query, no new fit.
  if (requested.raster == RasterPath::kAuto)
    throw std::invalid_argument("G2LF on the GPU: resolve --raster auto before rendering");
  const PlaneRequest request{requested.format(), requested.plane_raster, requested.raster, o.chunks, wp, hp,
                             requested.accumulation_budget_bytes, requested.memory_budget_bytes};
  if (tile_raster_) tile_raster_->set_split_keys(requested.compute_split_keys);
  if (request_ && *request_ == request) {
    GlG2lfOptions drawn = requested;
    drawn.plane_raster = raster_;
    return check_g2lf_fits(drawn, geometry, scene_.size(), info_, std::nullopt);
  }
  const size_t held = sweeping_.bytes() + buffers_.bytes() + layers_.bytes() + sort_.scratch_bytes() +
                      plane_raster_.bytes() + (tile_raster_ ? tile_raster_->bytes() : 0);
  // What the driver says is free, plus what this renderer would give back before allocating.
  std::optional<long long> free_bytes;
  if (requested.memory_budget_bytes == 0) {
    free_bytes = query_gl_info(info_.platform).free_memory_bytes;
    if (free_bytes) *free_bytes += (long long)held;
  }
  const GlG2lfOptions options = g2lf_fitting_options(requested, geometry, scene_.size(), free_bytes);
  check_g2lf_fits(options, geometry, scene_.size(), info_, free_bytes);
  if (!sweeping_.has_planes(options.format(), o.chunks, wp, hp)) sweeping_.allocate_planes(options.format(), o.chunks, wp, hp);
  batch_layers_ = batch_layers_for(options, geometry);  // GlPlaneRaster sizes its accumulation array to it
  raster_ = options.plane_raster;
  raster_path_ = options.raster;
  if (raster_path_ == RasterPath::kCompute && !tile_raster_) {
    tile_raster_ = std::make_unique<GlSplatTileRaster>();
    tile_raster_->set_split_keys(requested.compute_split_keys);
  }
  request_ = request;
}

void GlG2lfRenderer::preprocess(const render::ReferenceCamera& ref, const render::QuiltGeometry& geometry,
                                const render::G2lfOptions& o, const render::RasterSettings& settings) {
  // The planes' rasterizer settings, as render_quilt_g2lf and render_sweeping_planes set them.
  render::RasterSettings plane_settings = settings;
  if (o.adaptive_filter)
    plane_settings.dilation_px2 =
        render::adaptive_filter_variance(geometry, ref, o.plane_scale, settings.dilation_px2);
  plane_settings.background = glm::vec3(0.0f);
  plane_settings.sh_origin = geometry.base.position_world;
  preprocess_.run(scene_, ref.camera, plane_settings, buffers_);
}

void GlG2lfRenderer::bin(const render::ReferenceCamera& ref, const render::G2lfOptions& o, GlPlanes& planes,
                         bool binned_only) {
  // Overwrites the preprocess's keys and values (the planes need the binning's order) and sets
  // the draw's instance count to the binned count; culled records are zero and draw nothing.
  binning_.run(scene_, ref, o.chunks, o.binning, sort_, buffers_.keys, buffers_.values, layers_, planes.table,
               &buffers_.draw, binned_only);
}

void GlG2lfRenderer::draw_planes(GlPlanes& planes) {
  if (raster_path_ == RasterPath::kCompute)
    return tile_raster_->render_planes(buffers_.records, buffers_.values, layers_, buffers_.draw, scene_.size(),
                                       planes);
  plane_raster_.run(buffers_.records, buffers_.values, layers_, buffers_.draw, scene_.size(), batch_layers_,
                    planes);
}

void GlG2lfRenderer::record_stats(bool timed, TimerReads reads) {
  const GlPlanes& planes = sweeping_.planes();
  const GlG2lfStats last = stats_;
  stats_ = {};
  stats_.plane_bytes = planes.texels.bytes();
  stats_.plane_format = planes.format;
  stats_.plane_raster = raster_;
  stats_.raster = raster_path_;
  if (tile_raster_ && raster_path_ == RasterPath::kCompute) stats_.compute_keys = tile_raster_->counts().keys;
  stats_.gpu_bytes = scene_.bytes() + sweeping_.bytes() + buffers_.bytes() + layers_.bytes() +
                     sort_.scratch_bytes() + plane_raster_.bytes() + (tile_raster_ ? tile_raster_->bytes() : 0);
  stats_.gpu_bytes_peak = gpu_bytes_peak();
  if (!timed) return;
  const std::optional<GlSweepingPlaneReadout> r = sweeping_.readout(reads);
  if (!r) {  // kLate, no timed frame finished yet (or none since): the last figures stay
    stats_.gaussians_in_frustum = last.gaussians_in_frustum;
    stats_.planes = last.planes;
    stats_.plane_bytes_used = last.plane_bytes_used;
    stats_.seconds_planes = last.seconds_planes;
    stats_.seconds_binning = last.seconds_binning;
    stats_.seconds_swizzle = last.seconds_swizzle;
    stats_.frames_late = last.frames_late;
    return;
  }
  stats_.gaussians_in_frustum = r->header.splats_binned;
  stats_.planes = int(r->header.plane_count);
  stats_.plane_bytes_used = plane_texture_bytes(planes.format, stats_.planes, planes.width, planes.height);
  stats_.seconds_planes = r->seconds.planes;
  stats_.seconds_binning = r->seconds.binning;
  stats_.seconds_swizzle = r->seconds.swizzle;
  stats_.frames_late = r->frames_late;
}

GlSweepingPlaneStages GlG2lfRenderer::frame_stages(const render::QuiltGeometry& geometry,
                                                   const GlG2lfOptions& options,
                                                   const render::RasterSettings& settings) {
  const render::G2lfOptions& o = options.g2lf;
  ensure_planes(options, geometry);
  GlSweepingPlaneStages stages;
  stages.prepare = [this, &geometry, &o, &settings](const render::ReferenceCamera& ref) {
    preprocess(ref, geometry, o, settings);
  };
  const bool binned_only = options.sort_binned_only;
  stages.bin = [this, &o, binned_only](const render::ReferenceCamera& ref, GlPlanes& planes) {
    bin(ref, o, planes, binned_only);
  };
  stages.draw_planes = [this](const render::ReferenceCamera&, GlPlanes& planes) { draw_planes(planes); };
  return stages;
}

void GlG2lfRenderer::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                  const GlG2lfOptions& options, const render::RasterSettings& settings,
                                  const Texture& quilt) {
  const render::G2lfOptions& o = options.g2lf;
  o.check(geometry);
  check_quilt_target("G2LF on the GPU", geometry, layout, quilt);
  sweeping_.set_swizzle({options.swizzle_views, options.swizzle_table, options.swizzle_hardware_bilinear});
  sweeping_.render_quilt(frame_stages(geometry, options, settings), geometry, layout, o, settings.background, quilt,
                         options.gpu_timers, "a G2LF frame");
  record_stats(options.gpu_timers, options.timer_reads);
}

void GlG2lfRenderer::render_panel(const render::QuiltGeometry& geometry, const GlG2lfOptions& options,
                                  const render::RasterSettings& settings, GlDirectPanel& pass,
                                  const interlace::DirectPanelOptions& panel_options, Texture& panel) {
  const render::G2lfOptions& o = options.g2lf;
  o.check(geometry);
  sweeping_.render_planes(
      frame_stages(geometry, options, settings), geometry, o,
      [&](const GlPlanes& planes, const render::ReferenceCamera& ref) {
        pass.run(planes, geometry, ref, panel_options, panel);
      },
      options.gpu_timers, "a G2LF direct panel frame");
  record_stats(options.gpu_timers, options.timer_reads);
}

ImageF render_quilt_g2lf_gl(const scene::GaussianScene& scene, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout& layout, const GlG2lfOptions& options,
                            const render::RasterSettings& settings, GlG2lfStats* stats) {
  options.g2lf.check(geometry);
  const GlInfo info = query_gl_info("current context");
  const GlScene gl_scene(scene, info);
  GlG2lfRenderer renderer(gl_scene, info);
  const Texture quilt = make_quilt_texture(layout, GL_RGBA32F);
  renderer.render_quilt(geometry, layout, options, settings, quilt);
  if (stats) *stats = renderer.stats();
  return read_image_top_down(quilt, 3);
}

}  // namespace lfd::gpu
