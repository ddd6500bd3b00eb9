// The throughput probe's memory bandwidth (gpu/probes/gl_throughput_probe.hpp): one vec4 read and one
// written per invocation, so a dispatch moves 32 bytes an invocation through DRAM.
#include "gpu/probes/shaders/probe_io.h"

layout(local_size_x = kProbeGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"
layout(std430, binding = kProbeSourceBinding) readonly buffer In { vec4 source[]; };
layout(std430, binding = kProbeTargetBinding) writeonly buffer Out { vec4 target[]; };
uniform uint count;

void main() {
  uint i = flat_invocation_index();
  if (i < count) target[i] = source[i] * 1.0001;
}
