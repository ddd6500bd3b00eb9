// Radix sort pass 3 (gpu/compute/gl_radix_sort.hpp): each block writes its elements to
// base(digit) + offset(digit, block) + (stable rank among the block's earlier equal digits).
// The rank within a kRadixTile-element tile comes from a bit mask per digit in shared memory (each
// thread sets its bit, then counts the bits of lower threads), which does what a subgroup
// match/ballot would without needing the extension.
#include "gpu/compute/shaders/radix_common.glsl"

layout(local_size_x = kRadixTile) in;

layout(std430, binding = kRadixKeysInBinding) readonly buffer KeysIn { uint keys_in[]; };
layout(std430, binding = kRadixBlockCountsBinding) readonly buffer BlockCounts { uint block_offsets[]; };
layout(std430, binding = kRadixDigitTotalsBinding) readonly buffer DigitTotals { uint digit_totals[]; };
layout(std430, binding = kRadixValuesInBinding) readonly buffer ValuesIn { uint values_in[]; };
layout(std430, binding = kRadixKeysOutBinding) writeonly buffer KeysOut { uint keys_out[]; };
layout(std430, binding = kRadixValuesOutBinding) writeonly buffer ValuesOut { uint values_out[]; };

uniform uint shift;

shared uint scan[kRadixDigits];
shared uint digit_cursor[kRadixDigits];  // where the block's next element of each digit goes
const uint kMaskWords = kRadixTile / 32u;
shared uint masks[kRadixDigits * kMaskWords];  // [digit][kRadixTile bits]: which threads of the tile hold the digit

void main() {
  uint tid = gl_LocalInvocationID.x;
  uint block = gl_WorkGroupID.x;

  // Exclusive scan of the digit totals: the start of each digit in the output.
  uint total = digit_totals[tid];
  scan[tid] = total;
  barrier();
  for (uint offset = 1u; offset < kRadixDigits; offset <<= 1) {
    uint add = tid >= offset ? scan[tid - offset] : 0u;
    barrier();
    scan[tid] += add;
    barrier();
  }
  digit_cursor[tid] = scan[tid] - total + block_offsets[tid * pass_block_count() + block];

  uint items = pass_block_items();
  uint begin = block * items;
  uint end = min(begin + items, pass_count());
  for (uint tile = begin; tile < end; tile += kRadixTile) {
    for (uint w = 0u; w < kMaskWords; ++w) masks[tid * kMaskWords + w] = 0u;
    barrier();
    uint k = tile + tid;
    uint raw = k < end ? keys_in[k] : 0xFFFFFFFFu;
    bool valid = k < end && !dropped(raw);
    uint key = pass_key(raw);
    uint digit = (key >> shift) & (kRadixDigits - 1u);
    uint word = tid >> 5, bit = tid & 31u;
    if (valid) atomicOr(masks[digit * kMaskWords + word], 1u << bit);
    barrier();
    if (valid) {
      uint rank = bitCount(masks[digit * kMaskWords + word] & ((1u << bit) - 1u));
      for (uint w = 0u; w < word; ++w) rank += bitCount(masks[digit * kMaskWords + w]);
      uint dst = digit_cursor[digit] + rank;
      keys_out[dst] = key;
      values_out[dst] = values_in[k];
    }
    barrier();
    uint tile_count = 0u;
    for (uint w = 0u; w < kMaskWords; ++w) tile_count += bitCount(masks[tid * kMaskWords + w]);
    digit_cursor[tid] += tile_count;
    barrier();
  }
}
