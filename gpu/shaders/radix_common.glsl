// Shared by the radix sort passes (gpu/gl_radix_sort.hpp; prepended to each): where a pass
// finds its element count and block layout, and which key it sorts.
//
// A sort that drops culled keys (0xFFFFFFFF) does so in its first pass, over the caller's
// count; radix_setup then writes the kept count, the block layout for it and the work-group
// count of the later passes into SortParams, which those passes read and are dispatched from
// (glDispatchComputeIndirect): nothing returns to the CPU.
layout(std430, binding = 6) buffer SortParams {
  uint param_count;
  uint param_block_count;
  uint param_block_items;
  uint param_pad;
  uint param_groups_x, param_groups_y, param_groups_z;  // DispatchIndirectCommand
};
// The kept keys' smallest and largest value (positive depth float bits), for normalised keys.
layout(std430, binding = 7) readonly buffer KeyRange { uint range_min; uint range_max; };

uniform uint count;        // elements of the first pass (the caller's count)
uniform uint block_count;  // its block layout
uniform uint block_items;  // a multiple of 256
uniform bool later_pass;   // count and layout from SortParams (a sort that drops keys, pass 2+)
uniform bool drop_culled;  // first pass: keys 0xFFFFFFFF are not counted nor written
uniform uint normalise_bits;  // first pass, > 0: keys become (key - range_min) >> s, s the
                              // smallest shift that fits the range in normalise_bits bits

uint pass_count() { return later_pass ? param_count : count; }
uint pass_block_count() { return later_pass ? param_block_count : block_count; }
uint pass_block_items() { return later_pass ? param_block_items : block_items; }

bool dropped(uint key) { return drop_culled && key == 0xFFFFFFFFu; }

// The key the first pass sorts by and writes (integer only, so every pass computes the same).
uint pass_key(uint key) {
  if (normalise_bits == 0u || key == 0xFFFFFFFFu) return key;
  const uint range = range_max - range_min;
  const int shift = max(0, findMSB(range) + 1 - int(normalise_bits));
  return (key - range_min) >> uint(shift);
}
