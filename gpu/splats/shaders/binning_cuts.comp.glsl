// G2LF depth binning, pass 2 (Alg. 1 line 2, FindQuantile; render/depth_binning.cpp): the cut
// positions in the sorted list of the n binned Gaussians, one invocation per cut:
//   cuts[k], k = 0..K          count quantiles n k / K (K = count_chunks)
//   cuts[K + m], m = 1..M-1    kMixed only: lower_bound of the depth z_m whose base-camera
//                              disparity is the m/M step from the nearest to the farthest
//                              binned Gaussian (M = disparity_chunks), in double as the CPU.
// Both runs are non-decreasing; the chunk pass merges them.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/planes/shaders/plane_table.glsl"
#include "gpu/splats/shaders/depth_key.glsl"

layout(local_size_x = kBinningCutsGroupSize) in;

layout(std430, binding = kSplatKeysBinding) readonly buffer Keys { uint keys[]; };  layout(std430, binding = kBinningCutsBinding) writeonly buffer Cuts { uint cuts[]; };

uniform uint count_chunks;      // K
uniform uint disparity_chunks;  // M (0: kQuantile)
uniform float d_forward_eff;    // reference depth + d_forward_eff = base depth

// The first sorted position whose depth is not below z (std::lower_bound on (depth, index)
// pairs with (z, 0): only the depth decides).
uint lower_bound(uint n, float z) {
  const uint bits = depth_key(z);
  uint lo = 0u, hi = n;
  while (lo < hi) {
    const uint mid = lo + (hi - lo) / 2u;
    if (keys[mid] < bits) lo = mid + 1u;
    else hi = mid;
  }
  return lo;
}

void main() {
  const uint c = gl_GlobalInvocationID.x;
  const uint n = table.splats_binned;
  if (c <= count_chunks) {
    // n k / K without 64-bit products: n = q K + r, so n k / K = q k + r k / K exactly.
    const uint q = n / count_chunks, r = n % count_chunks;
    cuts[c] = q * c + (r * c) / count_chunks;
    return;
  }
  const uint m = c - count_chunks;  // 1..M-1
  if (m >= disparity_chunks) return;
  if (n == 0u) {
    cuts[c] = 0u;
    return;
  }
  precise const double fwd = double(d_forward_eff);
  precise const double w_near = 1.0lf / (double(key_depth(keys[0])) + fwd);
  precise const double w_far = 1.0lf / (double(key_depth(keys[n - 1u])) + fwd);
  precise const float z = float(1.0lf / (w_near + (w_far - w_near) * double(m) / double(disparity_chunks)) - fwd);
  cuts[c] = lower_bound(n, z);
}
