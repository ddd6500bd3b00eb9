#pragma once
// The GL per-view 3DGS renderer (docs/gpu.md "Per-view renderer"; paper: the conventional quilt,
// the ground truth of Table 1): per view, the three passes of the reference forward pass,
// pass for pass beside the CPU stages (render/rasterizer_cpu.hpp):
//   preprocess  GlSplatPreprocess   (render::preprocess)
//   sort        GlRadixSort         (render::bin_and_sort; one global depth order, the per-tile
//                                    lists are what the quads cover)
//   raster      GlSplatRaster       (render::blend)
// with no CPU round trip inside a view or a quilt. The scene (GlScene) is uploaded once and
// shared with other renderers.
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_frame_ring.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/compute/gl_radix_sort.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/splats/gl_splat_preprocess.hpp"
#include "gpu/splats/gl_splat_raster.hpp"
#include "gpu/splats/gl_splat_tile_raster.hpp"
#include "gpu/gl/raster_path.hpp"
#include "render/blend.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::gpu {

// GPU seconds of the last render_view or render_quilt (summed over its views; 0 unless
// GlPerViewOptions::gpu_timers) and the renderer's GPU memory (scene, scratch, targets).
struct GlPerViewStats {
  double preprocess_s = 0.0, sort_s = 0.0, raster_s = 0.0;
  size_t memory_bytes = 0;
  int views = 0;
};

struct GlPerViewOptions {
  // kHardware: per view, the three passes below with the raster pipeline's instanced quads;
  // kCompute: every view in one pass of the compute tile rasterizer (GlSplatTileRaster; exact 32-bit
  // depth order, so the depth-key options below do not apply). kAuto must be resolved first
  // (gpu::resolve_raster_path).
  RasterPath raster = RasterPath::kHardware;
  // kCompute: the bytes of records one pass may bind (GlSplatTileRaster::set_pass_limit, a
  // SplatRecord a (view, Gaussian) entry; 0: the GPU's largest storage buffer).
  size_t compute_pass_limit = 0;
  // kCompute: a tile with more splats than this is composited in parts, merged after
  // (GlSplatTileRaster::set_split_keys; 0: never split).
  uint32_t compute_split_keys = kTileSplatSplitKeys;
  // Format of the (C, T) accumulation target: GL_RGBA32F (matches the CPU to rounding) or
  // GL_RGBA16F (half the bandwidth; ~1e-3 relative rounding per blend).
  GLenum accumulation_format = GL_RGBA32F;
  // Time each pass with GL_TIMESTAMP queries, read at the end of a render call, which waits
  // for the GPU (kWait: benchmarks), or a few frames late without waiting (kLate: the viewer;
  // the stats then hold the newest finished frame's times). Timestamps, not GL_TIME_ELAPSED:
  // llvmpipe's elapsed-time queries read 0 around compute dispatches.
  bool gpu_timers = false;
  TimerReads timer_reads = TimerReads::kWait;
  // The high bits of a depth key (its float's bits) the sort orders by: 32 is exact (4 radix
  // passes, the default); 24 (3 passes, the viewer's) keeps the sign, exponent and 15 mantissa
  // bits, so depths within a relative 2^-15 (3e-5) of each other keep the Gaussian order instead
  // of the depth order (docs/gpu.md, "Per-view renderer"). 8, 16, 24 or 32.
  int depth_key_bits = 32;
  // Keys normalised to the view's visible depth range (GlRadixSort, SortKeys::normalise_bits):
  // depth_key_bits (8, 16 or 24) spread over the range the visible splats span, instead of the
  // float bits' high bits; 16 normalised bits (2 passes) order about as finely as 24 float bits.
  bool normalised_depth_keys = false;
  // The sort's first pass drops the culled splats and the later passes run over the visible
  // ones only (indirect dispatches; docs/gpu.md "Sorting what is visible"). Exact either way
  // (a stable compaction); false sorts all N keys every pass, for comparison.
  bool sort_visible_only = true;
};

class GlPerViewRenderer {
 public:
  // Needs a current context; `scene` must outlive the renderer.
  explicit GlPerViewRenderer(const GlScene& scene, const GlPerViewOptions& options = {});

  // Renders one view into a texture of the camera's size in the accumulation format, GL rows
  // bottom-up (texel row 0 = the image's bottom row): rgb = C + T background (not clamped),
  // alpha = the final transmittance T. Valid until the next call.
  const Texture& render_view(const render::Camera& camera, const render::RasterSettings& settings = {});
  // render_view read back as the CPU reference's image (row 0 = top).
  render::RasterImage render_view_image(const render::Camera& camera, const render::RasterSettings& settings = {});

  // Every view of `geometry` into its tile of `quilt` (layout.width x layout.height; RGBA8,
  // RGBA16F or RGBA32F), as render::render_quilt_per_view places them: view 0 in the
  // bottom-left tile, tiles row-major upward; the texture is bottom-up, so read back and
  // flipped (read_quilt_image) it equals the CPU's top-down quilt. Outside the tiles: 0.
  // Alpha is 1 in the tiles. Float quilts are drawn into directly (each view's viewport is its
  // tile); RGBA8 ones through a float view target, then composited into the tile.
  void render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                    const render::RasterSettings& settings, Texture& quilt);

  const GlPerViewStats& stats() const { return stats_; }

 private:
  // Preprocess and sort the view of `camera` into buffers_ (timestamps 4 view .. 4 view + 2).
  void prepare(const render::Camera& camera, const render::RasterSettings& settings, int view);
  void ensure_view_target(int width, int height);
  // Starts a timed frame of `views` views (a ring of 4 stamps per view: start, preprocessed,
  // sorted, drawn); records timestamp `index`; ends the frame and reads its stats.
  void begin_timing(int views);
  void stamp(size_t index);
  // `timed` views of stamps (the compute path times its one pass as one view).
  void finish_stats(int views, int timed);
  // --raster compute: every camera of `cameras` into `target` in one pass.
  void render_compute(std::span<const render::Camera> cameras, const render::RasterSettings& settings,
                      const TileViewsTarget& target);
  // The framebuffer of `quilt` (made once per renderer, not per frame).
  GLuint quilt_framebuffer(const Texture& quilt);

  const GlScene& scene_;
  GlPerViewOptions options_;
  GlSplatPreprocess preprocess_;
  GlRadixSort sort_;
  GlSplatRaster raster_;
  SplatBuffers buffers_;
  Texture view_target_;
  Framebuffer view_framebuffer_;
  Framebuffer quilt_framebuffer_;
  std::unique_ptr<GlSplatTileRaster> tiles_;  // --raster compute
  std::optional<GlFrameRing> timers_;
  GlPerViewStats stats_;
};

// A texture read back as a top-down image (row 0 = the top) with `channels` (3 or 4) of RGBA.
ImageF read_image_top_down(const Texture& texture, int channels = 3);

}  // namespace lfd::gpu
