// Shared by the radix sort passes (gpu/compute/gl_radix_sort.hpp; #included by each): where a pass
// finds its element count and block layout, and which key it sorts.
//
// A sort that drops culled keys (0xFFFFFFFF) does so in its first pass, over the caller's
// count; radix_setup then writes the kept count, the block layout for it and the work-group
// count of the later passes into SortParams, which those passes read and are dispatched from
// (glDispatchComputeIndirect): nothing returns to the CPU.
#include "gpu/compute/shaders/radix_sort_io.h"

layout(std430, binding = kRadixParamsBinding) buffer SortParams { RadixSortParams params; };
// The kept keys' smallest and largest value (positive depth float bits), for normalised keys.
layout(std430, binding = kRadixKeyRangeBinding) readonly buffer KeyRange { uint range_min; uint range_max; };

uniform uint count;        // elements of the first pass (the caller's count)
uniform uint block_count;  // its block layout
uniform uint block_items;  // a multiple of kRadixTile
uniform bool later_pass;   // count and layout from SortParams (a sort that drops keys, pass 2+)
uniform bool drop_culled;  // first pass: keys 0xFFFFFFFF are not counted nor written
uniform uint normalise_bits;  // first pass, > 0: keys become (key - range_min) >> s, s the
                              // smallest shift that fits the range in normalise_bits bits

uint pass_count() { return later_pass ? params.count : count; }
uint pass_block_count() { return later_pass ? params.block_count : block_count; }
uint pass_block_items() { return later_pass ? params.block_items : block_items; }

bool dropped(uint key) { return drop_culled && key == 0xFFFFFFFFu; }

// The key the first pass sorts by and writes (integer only, so every pass computes the same).
uint pass_key(uint key) {
  if (normalise_bits == 0u || key == 0xFFFFFFFFu) return key;
  const uint range = range_max - range_min;
  const int shift = max(0, findMSB(range) + 1 - int(normalise_bits));
  return (key - range_min) >> uint(shift);
}
