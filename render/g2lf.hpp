#pragma once
// G2LF on the CPU (paper section "G2LF" and Alg. 1): the sweeping-plane skeleton
// (sweeping_plane_pipeline.hpp, shared with V2LF) with Gaussians as the primitives. Its stages,
// each behind its own header:
//   depth_binning.hpp    cull to the reference frustum, bin by reference-camera depth into
//                        N_chunk chunks (Alg. 1 lines 1-3);
//   sweeping_planes.hpp  rasterise each chunk into its sweeping plane (premultiplied colour +
//                        transmittance, P_s x the view resolution, adaptive filter Eq.
//                        gs_prefilter_fix; lines 4-5);
//   swizzle_blend.hpp    composite the planes front to back into every quilt view (Eq. u_prime,
//                        Eq. alpha_blend; lines 6-12).
// The reference for the GL implementation.
#include <cstddef>
#include <string>

#include "render/depth_binning.hpp"
#include "scene/gaussian_scene.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/rasterizer_cpu.hpp"
#include "render/sweeping_plane_pipeline.hpp"
#include "render/sweeping_planes.hpp"
#include "render/swizzle_blend.hpp"
#include "util/image.hpp"

namespace lfd::render {

struct G2lfOptions {
  int chunks = 64;            // N_chunk, 1..4096
  int plane_scale = 1;        // P_s, 1..8
  // D_shift, scene units: the reference camera moves back from D_forward (reference_camera in
  // render/sweeping_plane_pipeline.hpp). Negative: D_forward,
  // i.e. the reference camera sits at the base camera, so content between the base camera and
  // D_forward (which the paper's D_shift = 0 drops) is kept; measured in docs/rendering.md.
  // At most D_forward (check(geometry)): further back, planes fall behind the view cameras.
  float d_shift = -1.0f;
  PlaneFilter filter = PlaneFilter::kNearest;
  PlanePrecision precision = PlanePrecision::kU8;  // the paper's default
  bool adaptive_filter = true;  // Eq. gs_prefilter_fix; false: the constant 0.3 px^2
  // Default kMixed: never worse than the paper's count quantiles in docs/rendering.md's
  // benchmark, much better on scenes with a large background; kQuantile is the paper's.
  ChunkBinning binning = ChunkBinning::kMixed;

  // Throws InputError "G2LF options: <field>: <problem>" for a value out of range.
  void check() const;
  // check() and what depends on the quilt geometry: D_shift must not exceed D_forward.
  void check(const QuiltGeometry& geometry) const;
};

// Option values by name; InputError "G2LF options: <field>: ..." for an unknown name.
PlaneFilter parse_plane_filter(const std::string& name);        // "nearest" | "bilinear"
PlanePrecision parse_plane_precision(const std::string& name);  // "u8" | "f32"
ChunkBinning parse_chunk_binning(const std::string& name);      // "quantile" | "mixed"

struct G2lfStats {
  size_t gaussians_in_frustum = 0;
  int planes = 0;
  size_t plane_bytes = 0;
  double seconds_binning = 0, seconds_planes = 0, seconds_swizzle = 0;
};

// Alg. 1 end to end. `settings.background` is the background; SH colours are evaluated from the
// base camera centre (the planes are shared by all views: paper, view-dependent trade-off).
// Checks `options` against `geometry` first (G2lfOptions::check).
ImageF render_quilt_g2lf(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                         const QuiltLayout& layout, const G2lfOptions& options,
                         const RasterSettings& settings = {}, G2lfStats* stats = nullptr);

// Alg. 1 lines 1-5 (binning and planes) with the same options, then `consume` with the planes
// (the direct panel pass, interlace/direct_panel.hpp); stats->seconds_swizzle is its time.
void render_planes_g2lf(const scene::GaussianScene& scene, const QuiltGeometry& geometry, const G2lfOptions& options,
                        const RasterSettings& settings, const PlaneConsumer& consume, G2lfStats* stats = nullptr);

}  // namespace lfd::render
