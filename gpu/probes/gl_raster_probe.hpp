#pragma once
// `--raster auto` (docs/gpu.md "Choosing the path: auto"): which way of drawing is faster on this
// device for what is drawn, measured, not guessed from its name. Per kind of scene, the probe
// renders one per-view quilt of a small generated scene both ways, one warm-up and three timed
// frames each (glFinish around a frame, wall clock), and takes the path with the smaller median;
// compute wins ties:
//   Gaussians  10k generated Gaussians, 4 views of 128x128
//   voxels     a generated level-5 voxel scene, 4 views of 96x96 (supersampled 1.5x, as scenes are)
// Each runs once per process (the first auto that needs it) and its answer is kept for the rest
// of the run: milliseconds on a GPU, seconds on llvmpipe.
#include <optional>
#include <string>

#include "gpu/gl/raster_path.hpp"
#include "scene/scene.hpp"

namespace lfd::gpu {

// What a raster path draws: Gaussians and voxels have different compute and raster passes, so
// each is measured on its own.
enum class RasterSubject { kGaussians, kVoxels };

// "Gaussians" | "voxels".
const char* raster_subject_name(RasterSubject subject);
// What a scene of `kind` is drawn as.
RasterSubject raster_subject_of(scene::SceneKind kind);

struct RasterProbe {
  RasterSubject subject = RasterSubject::kGaussians;
  double hardware_s = 0, compute_s = 0;  // median seconds of a probe quilt
  RasterPath faster = RasterPath::kCompute;  // or the one that works, when the other failed
  std::string hardware_failure, compute_failure;  // why a path failed on this device; empty: it ran
};

// Measures now (needs a current GL context). A path that fails is not chosen (a one-line notice
// on stderr says why); GlPathFailed when both fail.
RasterProbe probe_raster_paths(RasterSubject subject = RasterSubject::kGaussians);
// `requested`, or for kAuto the probe's choice for `subject` (measured on first use, then kept).
RasterPath resolve_raster_path(RasterPath requested, RasterSubject subject = RasterSubject::kGaussians);
// The probe this process ran for `subject`, if any (for reports).
std::optional<RasterProbe> last_raster_probe(RasterSubject subject = RasterSubject::kGaussians);

}  // namespace lfd::gpu
