#include "render/g2lf.hpp"

#include <chrono>
#include <cmath>

#include "util/error.hpp"

namespace lfd::render {

void G2lfOptions::check() const {
  if (chunks < 1 || chunks > 4096)
    throw_input_error("G2LF options: chunks: {} is outside 1..4096", chunks);
  if (plane_scale < 1 || plane_scale > 8)
    throw_input_error("G2LF options: plane_scale: {} is outside 1..8", plane_scale);
  if (!std::isfinite(d_shift)) throw_input_error("G2LF options: d_shift: must be finite");
}

void G2lfOptions::check(const QuiltGeometry& geometry) const {
  check();
  // Moved back further than D_forward, the reference camera sits behind the base camera
  // (D_forward_eff < 0): Gaussians behind the view cameras get planes at d_k <= 0, which
  // Eq. (u_prime) draws mirrored into every view.
  const float d_forward = make_reference_camera(geometry, 0.0f, 1).d_forward;
  if (d_shift > d_forward)
    throw_input_error("G2LF options: d_shift: {:.4g} is larger than D_forward {:.4g} of this quilt "
                      "geometry (the reference camera would sit behind the base camera and planes "
                      "behind the view cameras); use 0..{:.4g}, or a negative value for D_forward",
                      d_shift, d_forward, d_forward);
}

PlaneFilter parse_plane_filter(const std::string& name) {
  if (name == "nearest") return PlaneFilter::kNearest;
  if (name == "bilinear") return PlaneFilter::kBilinear;
  throw_input_error("G2LF options: filter: '{}' is not nearest or bilinear", name);
}

PlanePrecision parse_plane_precision(const std::string& name) {
  if (name == "u8") return PlanePrecision::kU8;
  if (name == "f32") return PlanePrecision::kF32;
  throw_input_error("G2LF options: precision: '{}' is not u8 or f32", name);
}

ChunkBinning parse_chunk_binning(const std::string& name) {
  if (name == "quantile") return ChunkBinning::kQuantile;
  if (name == "mixed") return ChunkBinning::kMixed;
  throw_input_error("G2LF options: binning: '{}' is not quantile or mixed", name);
}

ImageF render_quilt_g2lf(const GaussianScene& scene, const QuiltGeometry& geometry,
                         const QuiltLayout& layout, const G2lfOptions& options,
                         const RasterSettings& settings, G2lfStats* stats) {
  options.check(geometry);
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  const auto t0 = Clock::now();
  const float d_shift = options.d_shift >= 0.0f ? options.d_shift
                                                : make_reference_camera(geometry, 0.0f, 1).d_forward;
  const ReferenceCamera ref = make_reference_camera(geometry, d_shift, options.plane_scale);
  const DepthChunks chunks = bin_by_depth(scene, geometry, ref, options.chunks, options.binning);
  const auto t1 = Clock::now();
  RasterSettings plane_settings = settings;
  if (options.adaptive_filter)
    plane_settings.dilation_px2 =
        adaptive_filter_variance(geometry, ref, options.plane_scale, settings.dilation_px2);
  const SweepingPlanes planes =
      render_sweeping_planes(scene, geometry, ref, chunks, options.precision, plane_settings);
  const auto t2 = Clock::now();
  ImageF quilt(layout.width, layout.height, 3, 0.0f);
  swizzle_blend(planes, geometry, ref, layout, options.filter, settings.background, quilt);
  const auto t3 = Clock::now();
  if (stats) {
    stats->gaussians_in_frustum = 0;
    for (const auto& m : chunks.members) stats->gaussians_in_frustum += m.size();
    stats->planes = planes.count;
    stats->plane_bytes = planes.bytes();
    stats->seconds_binning = seconds(t0, t1);
    stats->seconds_planes = seconds(t1, t2);
    stats->seconds_swizzle = seconds(t2, t3);
  }
  return quilt;
}

}  // namespace lfd::render
