#pragma once
// G2LF stage 2 (paper section "Sweeping planes rendering", Alg. 1 lines 4-5): every chunk of
// Gaussians rasterised on its own from the reference camera into its sweeping plane, with
// the reference rasterizer and a zero background, so a texel holds the chunk's premultiplied
// colour C_k and its transmittance T_k. The planes are shared by all quilt views: this is
// where G2LF saves the per-view rasterisation, at the price of view-independent colour (SH
// evaluated once, from the base camera) and of each chunk flattened onto one depth.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "render/depth_binning.hpp"
#include "scene/gaussian_scene.hpp"
#include "render/blend.hpp"
#include "render/preprocess.hpp"
#include "render/quilt_geometry.hpp"

namespace lfd::render {

// Plane storage: 8-bit RGBT (the paper's default; value * 255 rounded, colour clamped to
// [0, 1]) or float (the paper's fp32 ablation).
enum class PlanePrecision { kU8, kF32 };

// The planes C (premultiplied RGB) and T, RGBA per texel.
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

// One plane per chunk, at the reference camera's resolution. `settings` are the rasterizer's
// (its dilation_px2 is the plane filter: G2LF passes the adaptive one of Eq. gs_prefilter_fix);
// the background is replaced by 0 and the SH origin by the base camera centre.
SweepingPlanes render_sweeping_planes(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                                      const ReferenceCamera& ref, const DepthChunks& chunks,
                                      PlanePrecision precision, const RasterSettings& settings);

// The same planes from any renderer of a chunk (V2LF's voxel rasterizer, voxel/v2lf.hpp):
// `render_chunk(k)` is chunk k's image from the reference camera at its resolution with a zero
// background; `order` the order to render them in (largest first balances the threads; empty:
// 0, 1, ...).
SweepingPlanes make_sweeping_planes(const ReferenceCamera& ref, const std::vector<float>& plane_depth,
                                    PlanePrecision precision, const std::function<RasterImage(int)>& render_chunk,
                                    const std::vector<int>& order = {});

}  // namespace lfd::render
