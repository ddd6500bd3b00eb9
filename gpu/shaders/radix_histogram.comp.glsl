// Radix sort pass 1 (gpu/gl_radix_sort.hpp): the digit counts of one block of keys.
layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer Keys { uint keys[]; };
// [digit * block_count + block]: digit-major, so one prefix scan per digit row gives each
// block its offset among the elements of that digit.
layout(std430, binding = 1) writeonly buffer BlockCounts { uint block_counts[]; };

uniform uint count;
uniform uint shift;
uniform uint block_count;
uniform uint block_items;  // a multiple of 256

shared uint local_counts[256];

void main() {
  uint tid = gl_LocalInvocationID.x;
  uint block = gl_WorkGroupID.x;
  local_counts[tid] = 0u;
  barrier();
  uint begin = block * block_items;
  uint end = min(begin + block_items, count);
  for (uint k = begin + tid; k < end; k += 256u) atomicAdd(local_counts[(keys[k] >> shift) & 255u], 1u);
  barrier();
  block_counts[tid * block_count + block] = local_counts[tid];
}
