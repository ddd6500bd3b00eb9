#pragma once
// G2LF on the GPU (paper Alg. 1; docs/gpu.md "G2LF on the GPU"): the twin of render/g2lf.hpp,
// the sweeping-plane skeleton (gpu/planes/gl_sweeping_planes.hpp, shared with V2LF) with Gaussians as
// the primitives. Its stages, each behind its own header, pass for pass beside the CPU's:
//   preprocess  GlSplatPreprocess from the reference camera, dilation = the adaptive filter
//               variance of Eq. gs_prefilter_fix, SH seen from the base camera centre
//               (render::render_sweeping_planes' settings)
//   binning     GlDepthBinning (render::bin_by_depth): cull, one sort by reference depth,
//               chunk cuts, plane table, per-splat layer
//   planes      GlPlaneRaster (render::render_sweeping_planes): GlSplatRaster's layered draw,
//               every chunk in one instanced indirect draw into the layers of a 2D array texture
//               (premultiplied colour + transmittance, zero background), blended in the planes'
//               format (u8 precision: RGBA16F planes); RGBA8 planes through batches of float
//               accumulation when RGBA16F planes exceed the budget
//   swizzle     GlSwizzle (render::swizzle_blend) into the quilt texture
// One frame is GPU work only: the plane count, the binned count and the draw's instance count
// stay on the GPU, so nothing waits for a read-back (the stage times and counts come through
// gpu/gl/gl_frame_ring.hpp, read frames late; docs/gpu.md "A frame that never waits").
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/splats/gl_depth_binning.hpp"
#include "gpu/panel/gl_direct_panel.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/gl_plane_raster.hpp"
#include "gpu/splats/gl_splat_tile_raster.hpp"
#include "gpu/gl/raster_path.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/compute/gl_radix_sort.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/splats/gl_splat_preprocess.hpp"
#include "gpu/splats/gl_splat_raster.hpp"
#include "gpu/planes/gl_sweeping_planes.hpp"
#include "gpu/planes/gl_swizzle.hpp"
#include "render/g2lf.hpp"
#include "util/image.hpp"

namespace lfd::gpu {

struct GlG2lfOptions {
  render::G2lfOptions g2lf;  // every option of the CPU path, with its defaults
  // Plane texel format; unset: the CPU precision's (f32 -> RGBA32F; u8 -> RGBA16F drawn
  // layered, RGBA8 batched). RGBA16F exists only here.
  std::optional<PlaneFormat> plane_format;
  // How the planes are drawn (gpu/splats/gl_plane_raster.hpp): kLayered blends every chunk straight
  // into the plane array in one draw; u8-precision planes are then RGBA16F (blending in RGBA8
  // rounds T at every step), and fall back to kBatched RGBA8 planes (float accumulation,
  // rounded once) when the RGBA16F ones exceed the memory budget (docs/gpu.md "Planes").
  PlaneRaster plane_raster = PlaneRaster::kLayered;
  // kHardware: the planes drawn as plane_raster says; kCompute: by the compute tile rasterizer
  // (GlSplatTileRaster::render_planes: keys (plane | tile), the non-empty pairs only), which sums in
  // float registers and writes each texel once, so u8-precision planes are RGBA8 (the CPU's,
  // rounded once) with no batches. kAuto must be resolved first (gpu::resolve_raster_path).
  RasterPath raster = RasterPath::kHardware;
  // kCompute: a (plane, tile) with more splats than this is composited in parts, merged after
  // (GlSplatTileRaster::set_split_keys; 0: never split).
  uint32_t compute_split_keys = kTileSplatSplitKeys;
  // GPU bytes G2LF may allocate (planes + per-Gaussian buffers); 0: the free memory the driver
  // reports, no limit beyond the texture limits when it reports none (llvmpipe).
  size_t memory_budget_bytes = 0;
  // Float accumulation for RGBA8/RGBA16F planes: layers of P_s W x P_s H x 16 bytes that fit
  // this (at least one); more layers, fewer batches (draws) per frame.
  size_t accumulation_budget_bytes = size_t(64) << 20;
  // Per-stage GPU timers, the plane and binned counts in the stats: read at the end of a frame,
  // which waits for the GPU (kWait: benchmarks, tests), or a few frames late without waiting
  // (kLate: the viewer; the stats then hold the newest finished timed frame's figures).
  bool gpu_timers = false;
  TimerReads timer_reads = TimerReads::kWait;
  // Views one swizzle invocation composites (gpu/planes/gl_swizzle.hpp; `lfd bench gpu-frame` compares).
  int swizzle_views = kSwizzleViewsPerInvocation;
  // The binning sort's first pass drops the Gaussians outside the reference frustum and the
  // later passes sort the binned ones only (GlDepthBinning; false: all N, for comparison).
  bool sort_binned_only = true;
  // The swizzle's views x planes table and hardware bilinear (gpu/planes/gl_swizzle.hpp SwizzleOptions).
  bool swizzle_table = SwizzleOptions{}.factor_table;
  bool swizzle_hardware_bilinear = SwizzleOptions{}.hardware_bilinear;

  PlaneFormat format() const {
    if (plane_format) return *plane_format;
    if (g2lf.precision == render::PlanePrecision::kU8 && plane_raster == PlaneRaster::kLayered &&
        raster != RasterPath::kCompute)
      return PlaneFormat::kRgba16f;
    return plane_format_for(g2lf.precision);
  }
};

struct GlG2lfStats {
  size_t gaussians_in_frustum = 0;  // binned (gpu_timers only)
  int planes = 0;                   // planes used this frame (gpu_timers only)
  size_t plane_bytes = 0;           // the plane array: N_chunk layers (what is allocated)
  PlaneFormat plane_format = PlaneFormat::kRgba8;  // of the plane array
  PlaneRaster plane_raster = PlaneRaster::kLayered;  // as drawn (kBatched: the budget's fallback)
  RasterPath raster = RasterPath::kHardware;          // the planes drawn by the raster or compute path
  uint32_t compute_keys = 0;  // --raster compute: the (plane, tile) keys of the frame
  size_t plane_bytes_used = 0;      // the layers in use (gpu_timers only; the CPU's plane_bytes)
  double seconds_binning = 0, seconds_planes = 0, seconds_swizzle = 0;  // GPU time (gpu_timers)
  uint64_t frames_late = 0;  // how many frames ago the timed figures were rendered (kLate)
  size_t gpu_bytes = 0;       // held by the scene and this renderer now
  size_t gpu_bytes_peak = 0;  // the process's peak of GPU allocations (gpu_bytes_peak())
};

// GPU bytes a frame needs beyond the scene: the plane array (N_chunk layers of P_s W x P_s H),
// and the rest: per-Gaussian buffers (records, keys, values, layers, the sort's copies, batch
// lists) and the float accumulation layers.
size_t g2lf_plane_array_bytes(const GlG2lfOptions& options, const render::QuiltGeometry& geometry);
// --raster compute: the rest holds the compute path's key buffers instead of the accumulation
// layers (GlSplatTileRaster::plane_path_bytes), their keys counted at kComputePlaneKeysPerGaussian.
size_t g2lf_other_bytes(const GlG2lfOptions& options, const render::QuiltGeometry& geometry, size_t gaussians);
// The (plane, tile) keys a Gaussian is counted at in the memory check of --raster compute (a frame's
// keys are known only after its scan; docs/gpu.md "Memory and passes" gives the measured ratios).
inline constexpr size_t kComputePlaneKeysPerGaussian = 4;

// Throws InputError (one line: what is needed, what there is, which option lowers it) when the
// planes exceed the texture limits of `info` (GL_MAX_TEXTURE_SIZE, GL_MAX_ARRAY_TEXTURE_LAYERS)
// or the budget: options.memory_budget_bytes, else `free_bytes` (the driver's figure) if known.
void check_g2lf_fits(const GlG2lfOptions& options, const render::QuiltGeometry& geometry,
                     size_t gaussians, const GlInfo& info, std::optional<long long> free_bytes);
// The options a frame is drawn with: `options`, except that u8-precision planes drawn layered
// (RGBA16F, twice RGBA8's bytes) that exceed the budget fall back to kBatched RGBA8 planes.
GlG2lfOptions g2lf_fitting_options(const GlG2lfOptions& options, const render::QuiltGeometry& geometry,
                                   size_t gaussians, std::optional<long long> free_bytes);

class GlG2lfRenderer {
 public:
  // Needs a current context; `scene` must outlive the renderer; `info` the context's limits.
  GlG2lfRenderer(const GlScene& scene, const GlInfo& info);

  // Alg. 1 into `quilt` (layout.width x layout.height; RGBA8, RGBA16F or RGBA32F; rows
  // bottom-up, view 0 bottom-left): rgb = the CPU's render_quilt_g2lf, alpha 1, 0 outside the
  // tiles. `settings.background` is the background. Checks options.g2lf against `geometry` and
  // the planes against the GPU first (InputError). Planes are kept between frames and
  // reallocated when N_chunk, P_s, the view size or the format change.
  void render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                    const GlG2lfOptions& options, const render::RasterSettings& settings,
                    const Texture& quilt);

  // Alg. 1 lines 1-5 as render_quilt, then `pass` (the direct panel pass) into `panel` instead
  // of the swizzle: the panel straight from the planes, no quilt (gpu/panel/gl_direct_panel.hpp).
  void render_panel(const render::QuiltGeometry& geometry, const GlG2lfOptions& options,
                    const render::RasterSettings& settings, GlDirectPanel& pass,
                    const interlace::DirectPanelOptions& panel_options, Texture& panel);
  const GlG2lfStats& stats() const { return stats_; }
  const GlPlanes& planes() const { return sweeping_.planes(); }  // the last frame's

 private:
  void ensure_planes(const GlG2lfOptions& options, const render::QuiltGeometry& geometry);
  // The stages of a frame with these options (checked against `geometry` and the GPU first).
  GlSweepingPlaneStages frame_stages(const render::QuiltGeometry& geometry, const GlG2lfOptions& options,
                                     const render::RasterSettings& settings);
  // The stages of a frame (gpu/planes/gl_sweeping_planes.hpp).
  void preprocess(const render::ReferenceCamera& ref, const render::QuiltGeometry& geometry,
                  const render::G2lfOptions& o, const render::RasterSettings& settings);
  void bin(const render::ReferenceCamera& ref, const render::G2lfOptions& o, GlPlanes& planes, bool binned_only);
  void draw_planes(GlPlanes& planes);
  void record_stats(bool timed, TimerReads reads);

  const GlScene& scene_;
  GlInfo info_;
  GlSplatPreprocess preprocess_;
  GlRadixSort sort_;
  GlDepthBinning binning_;
  GlPlaneRaster plane_raster_;
  std::unique_ptr<GlSplatTileRaster> tile_raster_;  // --raster compute, made on first use
  RasterPath raster_path_ = RasterPath::kHardware;  // as drawn
  GlSweepingPlanes sweeping_;
  SplatBuffers buffers_;
  Buffer layers_;
  int batch_layers_ = -1;  // float accumulation layers (0: drawn directly, kLayered)
  PlaneRaster raster_ = PlaneRaster::kLayered;  // as drawn (g2lf_fitting_options)
  // What the planes were allocated for (the options asked, before any fallback).
  struct PlaneRequest {
    PlaneFormat format;
    PlaneRaster raster;
    RasterPath path;
    int chunks, width, height;
    size_t accumulation_budget, budget;
    bool operator==(const PlaneRequest&) const = default;
  };
  std::optional<PlaneRequest> request_;
  GlG2lfStats stats_;
};

// render::render_quilt_g2lf on the GPU of the current context, for one-off renders: uploads the
// scene, renders into an RGBA32F quilt and reads it back (RGB, rows top-down, not clamped).
ImageF render_quilt_g2lf_gl(const scene::GaussianScene& scene, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout& layout, const GlG2lfOptions& options,
                            const render::RasterSettings& settings = {}, GlG2lfStats* stats = nullptr);

}  // namespace lfd::gpu
