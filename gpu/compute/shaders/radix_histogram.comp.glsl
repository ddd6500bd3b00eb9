// Radix sort pass 1 (gpu/compute/gl_radix_sort.hpp): the digit counts of one block of keys.
#include "gpu/compute/shaders/radix_common.glsl"

layout(local_size_x = kRadixTile) in;

layout(std430, binding = kRadixKeysInBinding) readonly buffer Keys { uint keys[]; };
// [digit * block_count + block]: digit-major, so one prefix scan per digit row gives each
// block its offset among the elements of that digit.
layout(std430, binding = kRadixBlockCountsBinding) writeonly buffer BlockCounts { uint block_counts[]; };

uniform uint shift;

shared uint local_counts[kRadixDigits];

void main() {
  uint tid = gl_LocalInvocationID.x;
  uint block = gl_WorkGroupID.x;
  local_counts[tid] = 0u;
  barrier();
  uint items = pass_block_items();
  uint begin = block * items;
  uint end = min(begin + items, pass_count());
  for (uint k = begin + tid; k < end; k += kRadixTile) {
    uint key = keys[k];
    if (!dropped(key)) atomicAdd(local_counts[(pass_key(key) >> shift) & (kRadixDigits - 1u)], 1u);
  }
  barrier();
  block_counts[tid * pass_block_count() + block] = local_counts[tid];
}
