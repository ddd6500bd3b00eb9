#pragma once
// V2LF on the CPU (paper section "V2LF -- Sparse Voxels to Light Field"): G2LF's sweeping-plane
// skeleton (render/sweeping_plane_pipeline.hpp) with voxels as the primitives. Voxels are
// binned into N_chunk chunks by the reference-camera depth of their centres with G2LF's
// binnings (render/depth_binning.hpp); a voxel whose depth extent straddles a chunk boundary is
// split into its 8 children (voxel/voxel_split.hpp, the density field unchanged), each binned by
// its own centre; every chunk is rendered into its plane by the exact voxel rasterizer (zero
// background, SH from the base camera, no supersampling), low-pass filtered in place of
// supersampling (voxel/plane_lowpass.hpp), and render/swizzle_blend.hpp composites the planes
// into every view.
#include <cstddef>

#include "render/g2lf.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::voxel {

struct V2lfOptions {
  // G2LF's options, all of them used: chunks, plane_scale, d_shift, filter, precision,
  // binning; adaptive_filter switches the planes' low-pass filter (voxel/plane_lowpass.hpp, the
  // paper's stand-in for supersampling, matched at the focal plane as Eq. gs_prefilter_fix
  // matches 3DGS's dilation) on or off.
  render::G2lfOptions planes;
  // Split a voxel while its reference-depth extent straddles a chunk boundary, up to this many
  // levels below its own (0: never; octree level 16 is the floor). Off by default: the field is
  // the same, but SVRaster samples each voxel K times at its own chord's midpoints, so children
  // move a sharp surface within the parent. With K = 8 splitting one level raises the PSNR
  // against per-view quilts (29.9 -> 31.7 dB at 128 chunks); with SVRaster's K = 1 it lowers it
  // (31.6 -> 29.1 dB) on the generated tabletop (docs/voxels.md).
  int split_levels = 0;

  // planes.check(geometry) and InputError "V2LF options: split_levels: ..." out of 0..4.
  void check(const render::QuiltGeometry& geometry) const;
};

// The voxels that V2LF renders, binned: `scene` is the input with the split voxels' children
// appended (a split parent stays in it but in no chunk); chunk members index it.
struct VoxelChunks {
  scene::VoxelScene scene;
  render::DepthChunks chunks;
  size_t voxels_split = 0;  // input voxels replaced by descendants
  size_t children = 0;      // descendants in the chunks
};

struct V2lfStats {
  size_t voxels_binned = 0;  // in the chunks, children included
  size_t voxels_split = 0;
  int planes = 0;
  size_t plane_bytes = 0;
  double seconds_binning = 0, seconds_planes = 0, seconds_swizzle = 0;
};

// Voxels with a corner in front of the reference camera, binned by centre depth (options.binning,
// options.chunks), straddling ones split up to `split_levels` deeper. Chunk boundaries are the
// centre depths where a chunk begins; plane depths are those of the binning before splitting.
VoxelChunks bin_voxels_by_depth(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                const render::ReferenceCamera& ref, int chunks,
                                render::ChunkBinning binning = render::ChunkBinning::kQuantile,
                                int split_levels = 0);

// The quilt; checks `options` first.
ImageF render_quilt_v2lf(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const V2lfOptions& options,
                         const glm::vec3& background, V2lfStats* stats = nullptr);

// Binning and planes with the same options, then `consume` with the planes (the direct panel
// pass, interlace/direct_panel.hpp); checks `options` first.
void render_planes_v2lf(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                        const V2lfOptions& options, const render::PlaneConsumer& consume,
                        V2lfStats* stats = nullptr);

// The same without splitting.
ImageF render_quilt_v2lf(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const render::G2lfOptions& options,
                         const glm::vec3& background);

}  // namespace lfd::voxel
