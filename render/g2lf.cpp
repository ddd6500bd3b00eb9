#include "render/g2lf.hpp"

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
  const float d_forward = forward_distance(geometry);
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

void render_planes_g2lf(const scene::GaussianScene& scene, const QuiltGeometry& geometry, const G2lfOptions& options,
                        const RasterSettings& settings, const PlaneConsumer& consume, G2lfStats* stats) {
  options.check(geometry);
  DepthChunks chunks;
  SweepingPlaneStages stages;
  stages.bin = [&](const ReferenceCamera& ref) -> const DepthChunks& {
    chunks = bin_by_depth(scene, geometry, ref, options.chunks, options.binning);
    return chunks;
  };
  stages.render_planes = [&](const ReferenceCamera& ref, const DepthChunks& binned) {
    RasterSettings plane_settings = settings;
    if (options.adaptive_filter)
      plane_settings.dilation_px2 =
          adaptive_filter_variance(geometry, ref, options.plane_scale, settings.dilation_px2);
    return render_sweeping_planes(scene, geometry, ref, binned, options.precision, plane_settings);
  };
  SweepingPlaneStats frame;
  run_sweeping_planes(stages, geometry, options, consume, stats ? &frame : nullptr);
  if (stats) {
    copy_plane_stats(frame, *stats);
    stats->gaussians_in_frustum = frame.binned;
  }
}

ImageF render_quilt_g2lf(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                         const QuiltLayout& layout, const G2lfOptions& options,
                         const RasterSettings& settings, G2lfStats* stats) {
  ImageF quilt;
  render_planes_g2lf(
      scene, geometry, options, settings,
      [&](const SweepingPlanes& planes, const ReferenceCamera& ref) {
        quilt = ImageF(layout.width, layout.height, 3, 0.0f);
        swizzle_blend(planes, geometry, ref, layout, options.filter, settings.background, quilt);
      },
      stats);
  return quilt;
}

}  // namespace lfd::render
