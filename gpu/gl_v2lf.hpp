#pragma once
// V2LF on the GPU (issue #13; paper section "V2LF"): the GL twin of voxel/v2lf.hpp, the
// sweeping-plane skeleton (gpu/gl_sweeping_planes.hpp, shared with G2LF) with voxels as the
// primitives. Its stages:
//   bin       voxel::bin_voxels_by_depth on the CPU, the same chunks (and split voxels) the
//             CPU path renders; when voxels were split, the split scene is uploaded for the
//             frame (its orders sorted again). group_by_octant: each chunk's voxels taken from
//             the scene's eight front-to-back orders in order, uploaded as one buffer of (chunk,
//             octant) ranges; the plane table written from the CPU's depths.
//   planes    per chunk, GlVoxelRaster from the reference camera (zero background, SH from the
//             base camera) into an RGBA32F accumulation layer, the low-pass filter
//             (voxel/plane_lowpass.hpp; gpu/shaders/voxel_plane_lowpass.comp.glsl) when
//             adaptive_filter, then rounded into its plane as the CPU stores it (G2LF's convert
//             pass, gpu/shaders/g2lf_plane_convert.comp.glsl)
//   swizzle   GlSwizzle into the quilt (the skeleton's)
// The binning stays on the CPU (one pass over the voxels per frame, O(8 n) for the grouping);
// the planes and the swizzle, where the time goes, are GPU work.
#include <functional>
#include <optional>
#include <vector>

#include "gpu/gl_context.hpp"
#include "gpu/gl_direct_panel.hpp"
#include "gpu/gl_g2lf.hpp"
#include "gpu/gl_objects.hpp"
#include "gpu/gl_planes.hpp"
#include "gpu/gl_splat_raster.hpp"
#include "gpu/gl_sweeping_planes.hpp"
#include "gpu/gl_voxel_raster.hpp"
#include "gpu/gl_voxel_scene.hpp"
#include "util/image.hpp"
#include "voxel/v2lf.hpp"

namespace lfd::gpu {

struct GlV2lfOptions {
  voxel::V2lfOptions v2lf;  // every option of the CPU path, with its defaults
  // Plane texel format; unset: the CPU precision's (u8 -> RGBA8, f32 -> RGBA32F).
  std::optional<PlaneFormat> plane_format;
  PlaneFormat format() const { return plane_format.value_or(plane_format_for(v2lf.planes.precision)); }
};

struct GlV2lfStats {
  int planes = 0;
  size_t voxels_binned = 0;  // in the chunks, split children included
  size_t voxels_split = 0;
  size_t plane_bytes = 0;  // the plane array
  size_t gpu_bytes = 0;    // scene + planes + accumulation + order buffer
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
  // of the swizzle: no quilt (gpu/gl_direct_panel.hpp).
  void render_panel(const render::QuiltGeometry& geometry, const GlV2lfOptions& options, GlDirectPanel& pass,
                    const interlace::DirectPanelOptions& panel_options, Texture& panel);
 private:
  void ensure_planes(PlaneFormat format, int max_planes, int width, int height);
  // The stages of a frame (gpu/gl_sweeping_planes.hpp): the chunks' voxels in every octant
  // order into chunk_orders_ (their ranges per chunk), then every plane drawn.
  std::vector<VoxelOrderRanges> upload_chunk_orders(const GlVoxelScene& scene, const render::DepthChunks& chunks,
                                                    const render::Camera& camera);
  void draw_planes(const GlVoxelScene& scene, const std::vector<VoxelOrderRanges>& ranges,
                   const render::ReferenceCamera& ref, const glm::vec3& sh_origin, float lowpass_variance,
                   GlPlanes& planes);
  void convert_plane(int k, const Program& convert, GlPlanes& planes);
  void lowpass(float variance_px2);
  void record_stats(const voxel::VoxelChunks& binned, const GlVoxelScene& scene);
  // One frame: the checks, the planes' allocation, the stages (binning on the CPU, planes on the
  // GPU) handed to `run`, which runs them with the swizzle or the direct pass; then the stats.
  void run_frame(const render::QuiltGeometry& geometry, const GlV2lfOptions& options,
                 const std::function<void(const GlSweepingPlaneStages&)>& run);

  const GlVoxelScene& scene_;
  GlInfo info_;
  GlVoxelRaster raster_;
  GlSplatRaster targets_;
  GlSweepingPlanes sweeping_;
  Program convert_u8_, convert_f16_, convert_f32_, lowpass_;
  Texture accumulation_;  // one RGBA32F layer of the planes' size
  Texture lowpass_scratch_;
  Framebuffer accumulation_framebuffer_;
  Buffer chunk_orders_;
  GlV2lfStats stats_;
};

// One-off: uploads the scene, renders into an RGBA32F quilt and reads it back (RGB, top-down).
ImageF render_quilt_v2lf_gl(const voxel::VoxelScene& scene, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout& layout, const GlV2lfOptions& options,
                            const glm::vec3& background, GlV2lfStats* stats = nullptr);

}  // namespace lfd::gpu
