#pragma once
// The sweeping-plane skeleton on the CPU (paper Alg. 1; docs/rendering.md), shared by G2LF
// (render/g2lf.hpp, Gaussians) and V2LF (voxel/v2lf.hpp, voxels): the reference camera, the
// primitives binned by reference depth into chunks, one plane per chunk, the swizzle blend of
// the planes into every view, and the time each stage took. What differs between the two (which
// primitives are binned, how a chunk becomes its plane) comes in through SweepingPlaneStages.
// The GL twin is gpu/planes/gl_sweeping_planes.hpp.
#include <cstddef>
#include <functional>

#include <glm/glm.hpp>

#include "render/depth_binning.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/sweeping_planes.hpp"
#include "util/image.hpp"

namespace lfd::render {

struct G2lfOptions;  // render/g2lf.hpp

// The reference camera of the planes: moved back from D_forward by options.d_shift, or, when
// d_shift < 0, by D_forward itself, which puts it at the base camera (docs/rendering.md).
ReferenceCamera reference_camera(const G2lfOptions& options, const QuiltGeometry& geometry);

// The two stages a sweeping-plane renderer supplies for one frame.
struct SweepingPlaneStages {
  // Alg. 1 lines 1-3: the primitives binned for the reference camera; the chunks must stay
  // valid until render_planes has returned.
  std::function<const DepthChunks&(const ReferenceCamera&)> bin;
  // Alg. 1 lines 4-5: one plane per chunk (make_sweeping_planes with the primitives' chunk
  // rasteriser).
  std::function<SweepingPlanes(const ReferenceCamera&, const DepthChunks&)> render_planes;
};

struct SweepingPlaneStats {
  size_t binned = 0;  // primitives in the chunks
  int planes = 0;
  size_t plane_bytes = 0;
  double seconds_binning = 0, seconds_planes = 0, seconds_swizzle = 0;
};

// The skeleton's figures into a method's own stats (G2lfStats, V2lfStats: the same fields;
// each names what `binned` counts itself).
template <typename MethodStats>
void copy_plane_stats(const SweepingPlaneStats& frame, MethodStats& stats) {
  stats.planes = frame.planes;
  stats.plane_bytes = frame.plane_bytes;
  stats.seconds_binning = frame.seconds_binning;
  stats.seconds_planes = frame.seconds_planes;
  stats.seconds_swizzle = frame.seconds_swizzle;
}

// What a frame does with its planes once they exist: the swizzle into a quilt (swizzle_blend.hpp,
// as render_quilt_g2lf and voxel::render_quilt_v2lf do), or the direct pass into a panel
// (interlace/direct_panel.hpp).
// Timed as the stage after the planes (SweepingPlaneStats::seconds_swizzle).
using PlaneConsumer = std::function<void(const SweepingPlanes&, const ReferenceCamera&)>;

// Alg. 1 lines 1-5 with `stages`, then `consume` with the planes; the caller has checked
// `options` against `geometry`.
void run_sweeping_planes(const SweepingPlaneStages& stages, const QuiltGeometry& geometry,
                         const G2lfOptions& options, const PlaneConsumer& consume,
                         SweepingPlaneStats* stats = nullptr);

}  // namespace lfd::render
