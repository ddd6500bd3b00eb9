// G2LF depth binning, pass 3 (Alg. 1 line 3, Sort_and_Chunk; render/depth_binning.cpp), one
// workgroup: merges the count cuts (recomputed) and the disparity cuts (from pass 2) into one
// sorted run, so a chunk lies between neighbours; equal neighbours are the CPU's duplicate cuts
// and give empty chunks, which are dropped, as the CPU does. The non-empty chunks become the
// planes, front to back: plane p gets its first sorted splat and d_k = the median reference
// depth of its members + D_forward_eff (base-camera depth, Eq. u_prime). Also sets the
// indirect draw's instance count to the binned count (the layered raster draws those).
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/depth_key.glsl"

layout(local_size_x = kBinningChunksGroupSize) in;

const uint kThreads = kBinningChunksGroupSize;

layout(std430, binding = kSplatKeysBinding) readonly buffer Keys { uint keys[]; };  // sorted
layout(std430, binding = kSplatDrawBinding) buffer Draw { uint draw_count; uint draw_instances; uint draw_first; uint draw_base; };
layout(std430, binding = kPlaneTableBinding) buffer PlaneTable {
  PlaneTableHeader table;
  PlaneTableEntry plane[];
};
layout(std430, binding = kBinningCutsBinding) readonly buffer Cuts { uint cuts[]; };

uniform uint count_chunks;      // K
uniform uint disparity_chunks;  // M (0: kQuantile)
uniform float d_forward_eff;

shared uint disparity[kBinningMaxDisparityChunks];
shared uint merged[kBinningMaxCuts];
shared uint planes_before[kThreads];

uint count_cut(uint n, uint k) {
  const uint q = n / count_chunks, r = n % count_chunks;
  return q * k + (r * k) / count_chunks;
}

// Disparity cuts below `value` (stable merge: count cuts go first among equals).
uint disparity_cuts_below(uint value, uint stored) {
  uint lo = 0u, hi = stored;
  while (lo < hi) {
    const uint mid = (lo + hi) / 2u;
    if (disparity[mid] < value) lo = mid + 1u;
    else hi = mid;
  }
  return lo;
}

// Count cuts not above `value`.
uint count_cuts_not_above(uint n, uint value) {
  uint lo = 0u, hi = count_chunks + 1u;
  while (lo < hi) {
    const uint mid = (lo + hi) / 2u;
    if (count_cut(n, mid) <= value) lo = mid + 1u;
    else hi = mid;
  }
  return lo;
}

float depth_at(uint i) { return key_depth(keys[i]); }

void main() {
  const uint tid = gl_LocalInvocationIndex;
  const uint n = table.splats_binned;
  const uint stored = disparity_chunks > 1u ? disparity_chunks - 1u : 0u;
  const uint total = count_chunks + 1u + stored;

  for (uint m = tid; m < stored; m += kThreads) disparity[m] = cuts[count_chunks + 1u + m];
  barrier();
  for (uint k = tid; k <= count_chunks; k += kThreads) {
    const uint c = count_cut(n, k);
    merged[k + disparity_cuts_below(c, stored)] = c;
  }
  for (uint m = tid; m < stored; m += kThreads) {
    const uint c = disparity[m];
    merged[m + count_cuts_not_above(n, c)] = c;
  }
  barrier();

  // Chunk i = [merged[i], merged[i + 1]); each thread takes a contiguous slice of chunks.
  const uint chunks = total - 1u;
  const uint slice = (chunks + kThreads - 1u) / kThreads;
  const uint first = min(tid * slice, chunks), last = min(first + slice, chunks);
  uint mine = 0u;
  for (uint i = first; i < last; ++i) mine += merged[i + 1u] > merged[i] ? 1u : 0u;
  planes_before[tid] = mine;
  barrier();
  if (tid == 0u) {
    uint sum = 0u;
    for (uint t = 0u; t < kThreads; ++t) {
      const uint v = planes_before[t];
      planes_before[t] = sum;
      sum += v;
    }
    table.plane_count = sum;
    plane[sum].begin = n;
    plane[sum].depth = 0.0;
    draw_instances = n;
  }
  barrier();
  uint p = planes_before[tid];
  for (uint i = first; i < last; ++i) {
    const uint b = merged[i], e = merged[i + 1u];
    if (e <= b) continue;
    const uint mid = b + (e - b - 1u) / 2u;
    precise const float median = ((e - b) & 1u) != 0u ? depth_at(mid) : 0.5 * (depth_at(mid) + depth_at(mid + 1u));
    precise const float depth = median + d_forward_eff;
    plane[p].depth = depth;
    plane[p].begin = b;
    ++p;
  }
}
