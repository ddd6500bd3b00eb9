#pragma once
// V2LF on the CPU (paper section "V2LF -- Sparse Voxels to Light Field"): G2LF's sweeping planes
// and swizzle blending with voxels as the primitives. Voxels are binned into N_chunk chunks of
// equal count by the reference-camera depth of their centres (each plane at its chunk's median
// base-camera depth), every chunk is rendered into its plane by the exact voxel rasterizer
// (zero background, SH from the base camera, no supersampling), and render/swizzle_blend.hpp
// composites the planes into every view. Not yet: splitting a voxel that straddles a chunk
// boundary into its children, and the paper's low-pass filter on the planes.
#include "render/g2lf.hpp"
#include "voxel/voxel_scene.hpp"

namespace lfd::voxel {

// Voxels with a corner in front of the reference camera, by centre depth, in `chunks` runs of
// equal size (the paper's quantile binning).
render::DepthChunks bin_voxels_by_depth(const VoxelScene& scene, const render::QuiltGeometry& geometry,
                                        const render::ReferenceCamera& ref, int chunks);

// The quilt. Uses options.chunks, plane_scale, d_shift, filter and precision (binning is always
// the quantile one; there is no adaptive filter for voxels).
ImageF render_quilt_v2lf(const VoxelScene& scene, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const render::G2lfOptions& options,
                         const glm::vec3& background);

}  // namespace lfd::voxel
