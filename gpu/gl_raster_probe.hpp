#pragma once
// `--raster auto` (docs/gpu.md "Choosing the path: auto"): which way of drawing Gaussians is
// faster on this device, measured, not guessed from its name. The probe renders one per-view
// quilt of a generated scene (10k Gaussians, 4 views of 128x128) both ways, one warm-up and three
// timed frames each (glFinish around a frame, wall clock), and takes the path with the smaller
// median; compute wins ties. It runs once per process (the first auto that needs it) and the
// answer is kept for the rest of the run: milliseconds on a GPU, about 2 s on llvmpipe.
#include <optional>

#include "gpu/raster_path.hpp"

namespace lfd::gpu {

struct RasterProbe {
  double hardware_s = 0, compute_s = 0;  // median seconds of a probe quilt
  RasterPath faster = RasterPath::kCompute;
};

// Measures now (needs a current GL context).
RasterProbe probe_raster_paths();
// `requested`, or for kAuto the probe's choice (measured on first use, then kept).
RasterPath resolve_raster_path(RasterPath requested);
// The probe this process ran, if any (for reports).
std::optional<RasterProbe> last_raster_probe();

}  // namespace lfd::gpu
