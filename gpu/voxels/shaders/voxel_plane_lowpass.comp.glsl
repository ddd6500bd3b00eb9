// V2LF's low-pass filter on a sweeping plane (voxel/plane_lowpass.cpp gaussian_lowpass), one
// axis per dispatch: a normalised Gaussian kernel (weights from the CPU, cut at 3 sigma) along
// x from the accumulation layer into a scratch image, then along y back into the layer, edges
// clamped, on (C, T) alike.
#include "gpu/planes/shaders/plane_io.h"

layout(local_size_x = kPlaneGroupWidth, local_size_y = kPlaneGroupHeight) in;

layout(rgba32f, binding = kPlaneAccumulationImage) uniform image2DArray accumulation;  // layer 0: the plane (C, T)
layout(rgba32f, binding = kPlaneLowpassScratchImage) uniform image2D scratch;

uniform ivec2 plane_size;
uniform int radius;
uniform int along_y;  // 0: accumulation -> scratch along x; 1: scratch -> accumulation along y
uniform float kernel[kLowpassMaxTaps];

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= plane_size.x || p.y >= plane_size.y) return;
  vec4 sum = vec4(0.0);
  for (int k = -radius; k <= radius; ++k) {
    if (along_y == 0) {
      ivec2 q = ivec2(clamp(p.x + k, 0, plane_size.x - 1), p.y);
      sum += kernel[k + radius] * imageLoad(accumulation, ivec3(q, 0));
    } else {
      ivec2 q = ivec2(p.x, clamp(p.y + k, 0, plane_size.y - 1));
      sum += kernel[k + radius] * imageLoad(scratch, q);
    }
  }
  if (along_y == 0)
    imageStore(scratch, p, sum);
  else
    imageStore(accumulation, ivec3(p, 0), sum);
}
