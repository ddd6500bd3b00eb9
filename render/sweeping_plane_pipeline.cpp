#include "render/sweeping_plane_pipeline.hpp"

#include <chrono>

#include "render/g2lf.hpp"

namespace lfd::render {

ReferenceCamera reference_camera(const G2lfOptions& options, const QuiltGeometry& geometry) {
  const float d_shift =
      options.d_shift >= 0.0f ? options.d_shift : forward_distance(geometry);
  return make_reference_camera(geometry, d_shift, options.plane_scale);
}

void run_sweeping_planes(const SweepingPlaneStages& stages, const QuiltGeometry& geometry,
                         const G2lfOptions& options, const PlaneConsumer& consume,
                         SweepingPlaneStats* stats) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  const auto t0 = Clock::now();
  const ReferenceCamera ref = reference_camera(options, geometry);
  const DepthChunks& chunks = stages.bin(ref);
  const auto t1 = Clock::now();
  const SweepingPlanes planes = stages.render_planes(ref, chunks);
  const auto t2 = Clock::now();
  consume(planes, ref);
  const auto t3 = Clock::now();
  if (stats) {
    stats->binned = 0;
    for (const auto& m : chunks.members) stats->binned += m.size();
    stats->planes = planes.count;
    stats->plane_bytes = planes.bytes();
    stats->seconds_binning = seconds(t0, t1);
    stats->seconds_planes = seconds(t1, t2);
    stats->seconds_swizzle = seconds(t2, t3);
  }
}

}  // namespace lfd::render
