// Radix sort, after the first pass of a sort that drops keys (gpu/gl_radix_sort.hpp): the kept
// count (the sum of the first pass's digit totals), its block layout as GlRadixSort::sort
// chooses one on the CPU, and the later passes' work-group count, into SortParams.
#include "gpu/shaders/radix_common.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = 2) readonly buffer DigitTotals { uint digit_totals[]; };

uniform uint target_blocks;        // GlRadixSort's kTargetBlocks
uniform uint max_tiles_per_block;  // and kMaxTilesPerBlock

shared uint partial[256];

void main() {
  uint tid = gl_LocalInvocationID.x;
  partial[tid] = digit_totals[tid];
  barrier();
  for (uint half_size = 128u; half_size > 0u; half_size >>= 1) {
    if (tid < half_size) partial[tid] += partial[tid + half_size];
    barrier();
  }
  if (tid == 0u) {
    uint kept = partial[0];
    uint tiles = (kept + 255u) / 256u;
    uint tiles_per_block = clamp((tiles + target_blocks - 1u) / target_blocks, 1u, max_tiles_per_block);
    uint items = tiles_per_block * 256u;
    // At least one block, so every pass moves the (possibly empty) run to its output copy.
    uint blocks = max(1u, (kept + items - 1u) / items);
    param_count = kept;
    param_block_count = blocks;
    param_block_items = items;
    param_groups_x = blocks;
    param_groups_y = 1u;
    param_groups_z = 1u;
  }
}
