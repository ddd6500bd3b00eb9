// The throughput probe's arithmetic rate (gpu/probes/gl_throughput_probe.hpp): per invocation
// `iterations` steps of 8 independent fused multiply-adds (2 FLOPs each), chains the compiler
// cannot fold, summed into one store so none is dropped.
#include "gpu/probes/shaders/probe_io.h"

layout(local_size_x = kProbeGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"
layout(std430, binding = kProbeTargetBinding) writeonly buffer Out { float result[]; };
uniform uint iterations;
uniform float seed;

void main() {
  uint i = flat_invocation_index();
  float x = seed * float(i & 1023u);
  vec4 a = vec4(x, x + 1.0, x + 2.0, x + 3.0), b = a + 4.0;
  const vec4 m = vec4(0.9999), c = vec4(0.0001);
  for (uint k = 0u; k < iterations; ++k) {
    a = fma(a, m, c);
    b = fma(b, m, c);
  }
  result[i] = dot(a + b, vec4(1.0));
}
