// Radix sort, after the first pass of a sort that drops keys (gpu/compute/gl_radix_sort.hpp): the kept
// count (the sum of the first pass's digit totals), its block layout as GlRadixSort::sort
// chooses one on the CPU, and the later passes' work-group count, into SortParams.
#include "gpu/compute/shaders/radix_common.glsl"

layout(local_size_x = kRadixTile) in;

layout(std430, binding = kRadixDigitTotalsBinding) readonly buffer DigitTotals { uint digit_totals[]; };

shared uint partial[kRadixDigits];

void main() {
  uint tid = gl_LocalInvocationID.x;
  partial[tid] = digit_totals[tid];
  barrier();
  for (uint half_size = kRadixDigits / 2u; half_size > 0u; half_size >>= 1) {
    if (tid < half_size) partial[tid] += partial[tid + half_size];
    barrier();
  }
  if (tid == 0u) {
    uint kept = partial[0];
    uint tiles = (kept + kRadixTile - 1u) / kRadixTile;
    uint tiles_per_block = clamp((tiles + kRadixTargetBlocks - 1u) / kRadixTargetBlocks, 1u, kRadixMaxTilesPerBlock);
    uint items = tiles_per_block * kRadixTile;
    // At least one block, so every pass moves the (possibly empty) run to its output copy.
    uint blocks = max(1u, (kept + items - 1u) / items);
    params.count = kept;
    params.block_count = blocks;
    params.block_items = items;
    params.groups_x = blocks;
    params.groups_y = 1u;
    params.groups_z = 1u;
  }
}
