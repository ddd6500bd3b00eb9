#pragma once
// G2LF on the CPU (paper section "G2LF" and Alg. 1): cull to the reference frustum, quantile-bin
// by reference-camera depth into N_chunk chunks, rasterise each chunk into its sweeping plane
// (premultiplied colour + transmittance, P_s x the view resolution, adaptive filter Eq.
// gs_prefilter_fix), then swizzle-blend the planes front to back into the quilt (Eq. u_prime,
// Eq. alpha_blend). The reference for the GL implementation.
#include <cstdint>
#include <string>
#include <vector>

#include "render/gaussian_scene.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/rasterizer_cpu.hpp"
#include "util/image.hpp"

namespace lfd::render {

enum class PlaneFilter { kNearest, kBilinear };
enum class PlanePrecision { kU8, kF32 };
// How the depth range is cut into chunks (stage 1).
//   kQuantile: the paper's: equal Gaussian counts per chunk. Any monotone key (depth, inverse
//     depth) gives the same chunks, so "quantiles of disparity" is the same method.
//   kMixed: the union of N_chunk/2 count quantiles and N_chunk/2 cuts uniform in inverse
//     base-camera depth (disparity) over the binned range. The disparity cuts bound every
//     chunk's parallax error (|dx_j| |1/z - 1/d_k|, and with D_shift < D_forward also the
//     error of the reference camera's forward offset) also where few, large Gaussians cover much of the
//     image (backgrounds, ground near the camera), which count quantiles give one or two
//     planes; the count cuts keep the paper's density where the Gaussians are.
enum class ChunkBinning { kQuantile, kMixed };

struct G2lfOptions {
  int chunks = 64;            // N_chunk
  int plane_scale = 1;        // P_s
  // D_shift, scene units: the reference camera moves back from D_forward. Negative: D_forward,
  // i.e. the reference camera sits at the base camera, so content between the base camera and
  // D_forward (which the paper's D_shift = 0 drops) is kept; measured in docs/rendering.md.
  float d_shift = -1.0f;
  PlaneFilter filter = PlaneFilter::kNearest;
  PlanePrecision precision = PlanePrecision::kU8;  // the paper's default
  bool adaptive_filter = true;  // Eq. gs_prefilter_fix; false: the constant 0.3 px^2
  // Default kMixed: never worse than the paper's count quantiles in docs/rendering.md's
  // benchmark, much better on scenes with a large background; kQuantile is the paper's.
  ChunkBinning binning = ChunkBinning::kMixed;
  void check() const;           // throws InputError naming the bad option
};

PlaneFilter parse_plane_filter(const std::string& name);        // "nearest" | "bilinear"
PlanePrecision parse_plane_precision(const std::string& name);  // "u8" | "f32"
ChunkBinning parse_chunk_binning(const std::string& name);      // "quantile" | "mixed"

// Stage 1 (depth_binning.cpp): Gaussians whose centre lies in the reference frustum (z > 0.2,
// |ndc| <= 1.3 as the rasterizer's guard band), sorted by reference depth and split into at most
// `chunks` runs (kQuantile: of equal size; kMixed: see ChunkBinning); each plane sits at the
// median depth of its chunk.
struct DepthChunks {
  std::vector<std::vector<uint32_t>> members;  // non-empty chunks, front to back
  std::vector<float> plane_depth;              // d_k: depth from the *base* camera (Eq. u_prime)
};
DepthChunks bin_by_depth(const GaussianScene& scene, const QuiltGeometry& geometry,
                         const ReferenceCamera& ref, int chunks,
                         ChunkBinning binning = ChunkBinning::kQuantile);

// Stage 2 (sweeping_planes.cpp): the planes C (premultiplied RGB) and T, RGBA per texel,
// either 8-bit (value * 255 rounded, colour clamped to [0, 1]) or float.
struct SweepingPlanes {
  int count = 0, width = 0, height = 0;
  PlanePrecision precision = PlanePrecision::kU8;
  std::vector<uint8_t> texels_u8;  // [plane][row][col][rgbT]
  std::vector<float> texels_f32;
  std::vector<float> plane_depth;  // d_k
  // Per plane and row: the first and last non-empty column (first > last: empty row). Lets the
  // swizzle skip empty space, which dominates sparse planes.
  std::vector<int32_t> row_first, row_last;
  size_t bytes() const;
};
SweepingPlanes render_sweeping_planes(const GaussianScene& scene, const QuiltGeometry& geometry,
                                      const ReferenceCamera& ref, const DepthChunks& chunks,
                                      const G2lfOptions& options, const RasterSettings& settings);

// Stage 3 (swizzle_blend.cpp): writes every view's tile of `quilt` (top-down RGB float image of
// the layout's size): C = sum_k (prod_{m<k} T_m) c_k + (prod T) background.
void swizzle_blend(const SweepingPlanes& planes, const QuiltGeometry& geometry,
                   const ReferenceCamera& ref, const QuiltLayout& layout, PlaneFilter filter,
                   const glm::vec3& background, ImageF& quilt);

struct G2lfStats {
  size_t gaussians_in_frustum = 0;
  int planes = 0;
  size_t plane_bytes = 0;
  double seconds_binning = 0, seconds_planes = 0, seconds_swizzle = 0;
};

// Alg. 1 end to end. `settings.background` is the background; SH colours are evaluated from the
// base camera centre (the planes are shared by all views: paper, view-dependent trade-off).
ImageF render_quilt_g2lf(const GaussianScene& scene, const QuiltGeometry& geometry,
                         const QuiltLayout& layout, const G2lfOptions& options,
                         const RasterSettings& settings = {}, G2lfStats* stats = nullptr);

}  // namespace lfd::render
