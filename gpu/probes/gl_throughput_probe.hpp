#pragma once
// `lfd bench gpu-probe` (docs/gpu.md "Choosing the path: auto"): what a GPU offers each raster
// path, so a GPU's table says which it favours and why: the arithmetic rate and the memory
// bandwidth of a compute dispatch (what the compute tile rasterizer runs on) and the fill rate of
// the raster pipeline with blending (what the hardware path's quads need). Each figure is the
// median of repeated runs after a warm-up, timed with glFinish around the work (wall clock).
#include <cstddef>

namespace lfd::gpu {

struct ThroughputProbeOptions {
  size_t invocations = size_t(1) << 20;  // FMA: invocations, each `fma_iterations` x 8 FMAs
  unsigned fma_iterations = 256;
  size_t copy_bytes = size_t(64) << 20;  // bandwidth: bytes read (as many written)
  int fill_size = 1024;                  // fill: an RGBA16F target of this side
  int fill_layers = 64;                  // full-target triangles blended per run
  int runs = 5, warmup = 1;
};

struct ThroughputProbe {
  double fma_gflops = 0;        // 2 FLOPs an FMA
  double bandwidth_gbs = 0;     // bytes read + written per second, 1e9
  double fill_gpixels = 0;      // blended fragments per second, 1e9
  double fma_s = 0, copy_s = 0, fill_s = 0;  // median seconds of one run
};

// Needs a current GL context.
ThroughputProbe probe_throughput(const ThroughputProbeOptions& options = {});

}  // namespace lfd::gpu
