#pragma once
// V2LF on the GPU (docs/gpu.md "Voxels on the GPU"; paper section "V2LF"): the GL twin of voxel/v2lf.hpp, the
// sweeping-plane skeleton (gpu/planes/gl_sweeping_planes.hpp, shared with G2LF) with voxels as the
// primitives. Its stages:
//   bin       on the GPU (gpu/voxels/gl_voxel_binning.hpp, the default): the voxels culled, sorted
//             by centre depth and chunked by G2LF's passes, each octant's front-to-back order
//             grouped by chunk, and the indirect draws of every (plane, octant) written; nothing
//             read back, the scene uploaded once. On the CPU (split voxels, or
//             GlV2lfOptions::gpu_binning false): voxel::bin_voxels_by_depth, the same chunks
//             and split voxels the CPU path renders (a split scene uploaded for the frame), each
//             chunk's voxels taken from the scene's eight orders (group_by_octant) and uploaded
//             as one buffer of (chunk, octant) ranges, the plane table from the CPU's depths.
//   planes    per chunk, GlVoxelRaster from the reference camera (zero background, SH from the
//             base camera) into an RGBA32F accumulation layer, the low-pass filter
//             (voxel/plane_lowpass.hpp; gpu/voxels/shaders/voxel_plane_lowpass.comp.glsl) when
//             adaptive_filter, then rounded into its plane as the CPU stores it (G2LF's convert
//             pass, gpu/splats/shaders/g2lf_plane_convert.comp.glsl)
//   swizzle   GlSwizzle into the quilt (the skeleton's)
// With the GPU binning a frame makes no CPU pass over the voxels and no upload: the plane count
// and the draw sizes stay on the GPU, so every possible plane (N_chunk) gets its draws and its
// filter and convert dispatches, all indirect: empty past the frame's plane count.
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "gpu/gl/gl_context.hpp"
#include "gpu/panel/gl_direct_panel.hpp"
#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/splats/gl_splat_raster.hpp"
#include "gpu/planes/gl_sweeping_planes.hpp"
#include "gpu/voxels/gl_voxel_binning.hpp"
#include "gpu/voxels/gl_voxel_raster.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "gpu/voxels/gl_voxel_tile_raster.hpp"
#include "gpu/gl/raster_path.hpp"
#include "util/image.hpp"
#include "voxel/v2lf.hpp"

namespace lfd::gpu {

struct GlV2lfOptions {
  voxel::V2lfOptions v2lf;  // every option of the CPU path, with its defaults
  // Plane texel format; unset: the CPU precision's (u8 -> RGBA8, f32 -> RGBA32F).
  std::optional<PlaneFormat> plane_format;
  // Bin on the GPU (gpu/voxels/gl_voxel_binning.hpp). false: the CPU's binning uploaded every frame,
  // the path before it (`lfd bench gpu-frame` compares both). Split voxels (v2lf.split_levels >
  // 0) always bin on the CPU: the split scene is made there.
  bool gpu_binning = true;
  // How the planes are drawn: the raster pipeline (GlVoxelRaster) or the compute tile rasterizer
  // (GlVoxelTileRaster; with the GPU binning, every plane's keys in one sort a frame). Not kAuto:
  // the caller resolves it (gpu::resolve_raster_path).
  RasterPath raster = RasterPath::kHardware;
  // GL_TIMESTAMP stage times and the plane table's counts through the frame ring, as G2LF's
  // (GlG2lfOptions::gpu_timers, timer_reads; docs/gpu.md "A frame that never waits").
  bool gpu_timers = false;
  TimerReads timer_reads = TimerReads::kWait;
  bool bins_on_gpu() const { return gpu_binning && v2lf.split_levels == 0; }
  PlaneFormat format() const { return plane_format.value_or(plane_format_for(v2lf.planes.precision)); }
};

struct GlV2lfStats {
  bool binned_on_gpu = false;
  // Binned on the CPU: this frame's; on the GPU: the newest timed frame's (gpu_timers), else 0.
  int planes = 0;
  size_t voxels_binned = 0;  // in the chunks, split children included
  size_t voxels_split = 0;
  size_t plane_bytes = 0;  // the plane array
  size_t gpu_bytes = 0;    // scene + planes + accumulation + order buffer (+ the GPU binning's)
  double seconds_binning = 0, seconds_planes = 0, seconds_swizzle = 0;  // GPU time (gpu_timers)
  uint64_t frames_late = 0;  // how many frames ago the timed figures were rendered (kLate)
};

class GlV2lfRenderer {
 public:
  // Needs a current context; `scene` outlives the renderer; `info` the context's limits.
  GlV2lfRenderer(const GlVoxelScene& scene, const GlInfo& info);

  // The CPU's render_quilt_v2lf into `quilt` (layout size; RGBA8, RGBA16F or RGBA32F; rows
  // bottom-up), every V2LF option; the planes are checked against the GPU's limits first
  // (InputError).
  void render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                    const GlV2lfOptions& options, const glm::vec3& background, const Texture& quilt);

  const GlV2lfStats& stats() const { return stats_; }
  const GlPlanes& planes() const { return sweeping_.planes(); }

  // Binning and planes as render_quilt, then `pass` (the direct panel pass) into `panel` instead
  // of the swizzle: no quilt (gpu/panel/gl_direct_panel.hpp).
  void render_panel(const render::QuiltGeometry& geometry, const GlV2lfOptions& options, GlDirectPanel& pass,
                    const interlace::DirectPanelOptions& panel_options, Texture& panel);
 private:
  void ensure_planes(PlaneFormat format, int max_planes, int width, int height);
  // The stages of a frame (gpu/planes/gl_sweeping_planes.hpp): the chunks' voxels in every octant
  // order into chunk_orders_ (their ranges per chunk), then every plane drawn.
  std::vector<VoxelOrderRanges> upload_chunk_orders(const GlVoxelScene& scene, const render::DepthChunks& chunks,
                                                    const render::Camera& camera);
  // Planes 0 .. count - 1: each cleared, `draw_chunk(k, target)` into the accumulation layer,
  // filtered and converted.
  using ChunkDraw = std::function<void(int k, const SplatRasterTarget& target)>;
  // `plane_dispatches`: the GPU binning's indirect dispatches of the per-plane passes (none past
  // the frame's plane count); nullptr: every plane below `count` is dispatched.
  struct PlaneDispatch;
  SplatRasterTarget accumulation_target(const GlPlanes& planes) const;  // the RGBA32F layer
  void draw_planes(int count, const ChunkDraw& draw_chunk, float lowpass_variance, const Buffer* plane_dispatches,
                   GlPlanes& planes);
  GlSweepingPlaneStages cpu_binned_stages(const render::QuiltGeometry& geometry, const GlV2lfOptions& options);
  GlSweepingPlaneStages gpu_binned_stages(const render::QuiltGeometry& geometry, const GlV2lfOptions& options);
  void convert_plane(int k, const Program& convert, const PlaneDispatch& dispatch, GlPlanes& planes);
  float lowpass_variance(const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref,
                         const render::G2lfOptions& o) const;
  // The planes' low-pass filter: its kernel once a frame (false: off), then per plane.
  bool prepare_lowpass(float variance_px2);
  void lowpass(int k, const PlaneDispatch& dispatch);
  void record_stats(const GlV2lfOptions& options);
  // One frame: the checks, the planes' allocation, the stages (binning on the CPU, planes on the
  // GPU) handed to `run`, which runs them with the swizzle or the direct pass; then the stats.
  void run_frame(const render::QuiltGeometry& geometry, const GlV2lfOptions& options,
                 const std::function<void(const GlSweepingPlaneStages&)>& run);

  const GlVoxelScene& scene_;
  GlInfo info_;
  GlVoxelRaster raster_;
  std::unique_ptr<GlVoxelTileRaster> tile_raster_;  // made when a frame asks for RasterPath::kCompute
  GlSplatRaster targets_;
  GlSweepingPlanes sweeping_;
  Program convert_u8_, convert_f16_, convert_f32_, lowpass_;
  Texture accumulation_;  // one RGBA32F layer of the planes' size
  Texture lowpass_scratch_;
  Framebuffer accumulation_framebuffer_;
  GlVoxelBinning binning_;
  // The CPU binning's frame: its chunks, the split scene (when voxels were split), the ranges.
  voxel::VoxelChunks cpu_binned_;
  std::optional<GlVoxelScene> split_scene_;
  std::vector<VoxelOrderRanges> ranges_;
  Buffer chunk_orders_;
  GlV2lfStats stats_;
};

// One-off: uploads the scene, renders into an RGBA32F quilt and reads it back (RGB, top-down).
ImageF render_quilt_v2lf_gl(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout& layout, const GlV2lfOptions& options,
                            const glm::vec3& background, GlV2lfStats* stats = nullptr);

}  // namespace lfd::gpu
