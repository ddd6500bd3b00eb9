// The key passes' count-then-emit shape (docs/gpu.md "The compute tile rasterizer"), shared by
// the tile rasterizers of voxels and of Gaussians: one invocation an item, compiled twice. EMIT 0
// counts the item's keys into counts[item]; GlTileKeys::scan turns the counts into each item's
// first key; EMIT 1 writes the keys (slot) and values (what the slot's list holds) from there, in
// the same order as it counted. Declares the counts, keys and values buffers (tile_io.h).
//   TileKeyWriter w = tile_keys_begin(item);
//   for (each tile the item covers) tile_keys_add(w, slot, value);
//   tile_keys_end(w, item);
// With TILE_KEY_CAPACITY defined, EMIT 1 writes no key past the uniform key_capacity (the
// buffers' size, GlTileKeys::scan_to_capacity); the count still says how many there were.
#include "gpu/compute/shaders/tile_io.h"

#if EMIT
layout(std430, binding = kTileCountsBinding) readonly buffer Counts { uint counts[]; };
layout(std430, binding = kTileKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kTileValuesBinding) writeonly buffer Values { uint values[]; };
#if defined(TILE_KEY_CAPACITY)
uniform uint key_capacity;
#endif
#else
layout(std430, binding = kTileCountsBinding) writeonly buffer Counts { uint counts[]; };
#endif

struct TileKeyWriter {
  uint first;  // the item's first key (EMIT 1)
  uint n;      // keys so far
};

TileKeyWriter tile_keys_begin(uint item) {
  TileKeyWriter w;
#if EMIT
  w.first = counts[item];
#else
  w.first = 0u;
#endif
  w.n = 0u;
  return w;
}

void tile_keys_add(inout TileKeyWriter w, uint slot, uint value) {
#if EMIT
#if defined(TILE_KEY_CAPACITY)
  if (w.first + w.n < key_capacity)
#endif
  {
    keys[w.first + w.n] = slot;
    values[w.first + w.n] = value;
  }
#endif
  ++w.n;
}

// EMIT 0: the count (an item with no keys must still end, to write its 0).
void tile_keys_end(TileKeyWriter w, uint item) {
#if !EMIT
  counts[item] = w.n;
#endif
}
