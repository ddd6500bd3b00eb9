#pragma once
// G2LF stage 1 (paper section "G2LF -- 3D Gaussians to Light Field", Alg. 1 lines 1-3:
// CulledDepth, FindQuantile, Sort_and_Chunk): the Gaussians whose centres lie in the
// reference camera's frustum, sorted by reference-camera depth and cut into chunks, one
// sweeping plane per chunk at the median depth of its members. Quantile cuts give every plane
// about the same number of Gaussians, so the planes cost about the same to rasterise; each
// Gaussian belongs to exactly one chunk (by its centre), which is the method's discretisation.
#include <cstdint>
#include <utility>
#include <vector>

#include "scene/gaussian_scene.hpp"
#include "render/quilt_geometry.hpp"

namespace lfd::render {

// How the depth range is cut into chunks.
//   kQuantile: the paper's: equal Gaussian counts per chunk. Any monotone key (depth, inverse
//     depth) gives the same chunks, so "quantiles of disparity" is the same method.
//   kMixed: the union of N_chunk/2 count quantiles and N_chunk/2 cuts uniform in inverse
//     base-camera depth (disparity) over the binned range. The disparity cuts bound every
//     chunk's parallax error (|dx_j| |1/z - 1/d_k|, and with D_shift < D_forward also the
//     error of the reference camera's forward offset) also where few, large Gaussians cover much of the
//     image (backgrounds, ground near the camera), which count quantiles give one or two
//     planes; the count cuts keep the paper's density where the Gaussians are.
enum class ChunkBinning { kQuantile, kMixed };

struct DepthChunks {
  std::vector<std::vector<uint32_t>> members;  // non-empty chunks, front to back
  std::vector<float> plane_depth;              // d_k: depth from the *base* camera (Eq. u_prime)
};

// Gaussians whose centre lies in the reference frustum (z > 0.2, |ndc| <= 1.3 as the
// rasterizer's guard band), sorted by reference depth and split into at most `chunks` runs
// (kQuantile: of equal size; kMixed: see ChunkBinning); each plane sits at the median depth of
// its chunk. Members keep scene order inside a chunk.
DepthChunks bin_by_depth(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                         const ReferenceCamera& ref, int chunks,
                         ChunkBinning binning = ChunkBinning::kQuantile);

// The chunking alone, for any primitives (V2LF's voxels, voxel/v2lf.hpp): `depth_index` holds
// (reference depth, primitive index) pairs of the primitives to bin, sorted ascending.
DepthChunks chunk_sorted_depths(const std::vector<std::pair<float, uint32_t>>& depth_index,
                                const ReferenceCamera& ref, int chunks,
                                ChunkBinning binning = ChunkBinning::kQuantile);

}  // namespace lfd::render
