// Scan pass 2 (gpu/compute/gl_tile_keys.hpp): one work group turns the block sums into each block's first
// offset, in kTileScanBlockItems chunks carried from one to the next, and writes the total keys.
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/compute/shaders/tile_scan.glsl"

layout(local_size_x = kTileScanGroupSize) in;
layout(std430, binding = kTileBlockSumsBinding) buffer BlockSums { uint block_sums[]; };
layout(std430, binding = kTileStateBinding) buffer State { TileState state; };
uniform uint block_count;

void main() {
  uint carry = 0u;
  for (uint base = 0u; base < block_count; base += kTileScanBlockItems) {
    uint first = base + gl_LocalInvocationIndex * kTileScanPerInvocation;
    uint v[kTileScanPerInvocation];
    uint sum = 0u;
    for (uint k = 0u; k < kTileScanPerInvocation; ++k) {
      v[k] = first + k < block_count ? block_sums[first + k] : 0u;
      sum += v[k];
    }
    uint total;
    uint offset = carry + group_exclusive_scan(sum, total);
    for (uint k = 0u; k < kTileScanPerInvocation; ++k) {
      if (first + k < block_count) block_sums[first + k] = offset;
      offset += v[k];
    }
    carry += total;
  }
  if (gl_LocalInvocationIndex == 0u) state.keys = carry;
}
