// Scan pass 3 (gpu/compute/gl_tile_keys.hpp): each block scans its counts again, from its first offset,
// into each item's first key (in place).
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/compute/shaders/tile_scan.glsl"

layout(local_size_x = kTileScanGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"
layout(std430, binding = kTileCountsBinding) buffer Counts { uint counts[]; };
layout(std430, binding = kTileBlockSumsBinding) readonly buffer BlockSums { uint block_sums[]; };
uniform uint item_count;

void main() {
  uint block = flat_group_index();
  uint first = block * kTileScanBlockItems + gl_LocalInvocationIndex * kTileScanPerInvocation;
  uint v[kTileScanPerInvocation];
  uint sum = 0u;
  for (uint k = 0u; k < kTileScanPerInvocation; ++k) {
    v[k] = first + k < item_count ? counts[first + k] : 0u;
    sum += v[k];
  }
  uint total;
  uint offset = block_sums[block] + group_exclusive_scan(sum, total);
  for (uint k = 0u; k < kTileScanPerInvocation; ++k) {
    if (first + k < item_count) counts[first + k] = offset;
    offset += v[k];
  }
}
