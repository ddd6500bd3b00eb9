// Scan pass 1 (gpu/compute/gl_tile_keys.hpp): each block of kTileScanBlockItems items sums its counts.
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/compute/shaders/tile_scan.glsl"

layout(local_size_x = kTileScanGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"
layout(std430, binding = kTileCountsBinding) readonly buffer Counts { uint counts[]; };
layout(std430, binding = kTileBlockSumsBinding) writeonly buffer BlockSums { uint block_sums[]; };
uniform uint item_count;

void main() {
  uint block = flat_group_index();
  uint first = block * kTileScanBlockItems + gl_LocalInvocationIndex * kTileScanPerInvocation;
  uint sum = 0u;
  for (uint k = 0u; k < kTileScanPerInvocation; ++k)
    if (first + k < item_count) sum += counts[first + k];
  uint total;
  group_exclusive_scan(sum, total);
  if (gl_LocalInvocationIndex == 0u) block_sums[block] = total;
}
