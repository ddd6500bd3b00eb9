// The throughput probe's passes (gpu/probes/gl_throughput_probe.hpp) on a tiny load: their
// declared bindings agree with their shaders and hold what each pass bound at its dispatches and
// draws (docs/gpu.md "Binding points"; CTest runs it under strict checks), and every figure is
// a positive rate.
#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/probes/gl_throughput_probe.hpp"

namespace lfd::gpu {
namespace {

TEST(GlThroughputProbe, EveryPassRunsAsDeclaredAndMeasuresARate) {
  HeadlessContext context;
  ThroughputProbeOptions o;
  o.invocations = 1024;
  o.fma_iterations = 4;
  o.copy_bytes = 64 << 10;
  o.fill_size = 32;
  o.fill_layers = 2;
  o.runs = 1;
  o.warmup = 0;
  const ThroughputProbe p = probe_throughput(o);
  EXPECT_GT(p.fma_gflops, 0.0);
  EXPECT_GT(p.bandwidth_gbs, 0.0);
  EXPECT_GT(p.fill_gpixels, 0.0);
}

}  // namespace
}  // namespace lfd::gpu
