// Radix sort pass 2 (gpu/compute/gl_radix_sort.hpp): one work group per digit turns its row of block
// counts into exclusive offsets and writes the digit's total.
#include "gpu/compute/shaders/radix_common.glsl"

layout(local_size_x = kRadixTile) in;

layout(std430, binding = kRadixBlockCountsBinding) buffer BlockCounts { uint block_counts[]; };
layout(std430, binding = kRadixDigitTotalsBinding) writeonly buffer DigitTotals { uint digit_totals[]; };

shared uint partial[kRadixTile];

void main() {
  uint tid = gl_LocalInvocationID.x;
  uint block_count = pass_block_count();
  uint row = gl_WorkGroupID.x * block_count;
  uint carry = 0u;
  for (uint base = 0u; base < block_count; base += kRadixTile) {
    uint i = base + tid;
    uint v = i < block_count ? block_counts[row + i] : 0u;
    partial[tid] = v;
    barrier();
    // Hillis-Steele inclusive scan of kRadixTile values.
    for (uint offset = 1u; offset < kRadixTile; offset <<= 1) {
      uint add = tid >= offset ? partial[tid - offset] : 0u;
      barrier();
      partial[tid] += add;
      barrier();
    }
    if (i < block_count) block_counts[row + i] = carry + partial[tid] - v;
    carry += partial[kRadixTile - 1u];
    barrier();
  }
  if (tid == 0u) digit_totals[gl_WorkGroupID.x] = carry;
}
