// The compute tile rasterizer's keys (gpu/gl_tile_splats.hpp), one invocation an item (a splat in
// one image, front to back): EMIT 0 counts the tiles it covers (tile_splat_cover.glsl) into
// counts[j], EMIT 1 writes its keys (slot = image * tiles + tile, value = its record) from its
// first key, counts[j] after the scan. Items with more than kTileSplatHugeTiles tiles in their
// rectangle are listed for tile_splat_huge.comp.glsl instead. PLANES 0: the image is the view,
// entry / gaussian_count; PLANES 1: the item's plane, layers[j].
#include "gpu/shaders/splat_record.glsl"
#include "gpu/shaders/tile_io.h"
#include "gpu/shaders/tile_splat_io.h"
#include "gpu/shaders/tile_splat_cover.glsl"
#include "gpu/shaders/tile_splat_item.glsl"
#include "gpu/shaders/frame_io.h"

layout(local_size_x = kTileSplatItemsGroupSize) in;

layout(std430, binding = kSplatRecordsBinding) readonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kTileSplatEntriesBinding) readonly buffer Entries { uint entries[]; };
layout(std430, binding = kTileSplatKeptBinding) readonly buffer Kept { uint kept_words[]; };
#if EMIT
layout(std430, binding = kTileCountsBinding) readonly buffer Counts { uint counts[]; };
layout(std430, binding = kTileKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kTileValuesBinding) writeonly buffer Values { uint values[]; };
#else
layout(std430, binding = kTileCountsBinding) writeonly buffer Counts { uint counts[]; };
layout(std430, binding = kTileSplatHugeBinding) buffer Huge { TileHugeList huge; uint huge_items[]; };
#endif

uniform uint item_capacity;  // items dispatched; those from the kept count on have no keys
uniform uint kept_word;      // the kept count's index in kept_words (the sort's params or a draw)
uniform ivec2 tile_grid;
#if EMIT
uniform uint key_capacity;  // keys the buffers hold (GlTileKeys::scan_to_capacity): none written past it
#endif

void main() {
  uint j = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (j >= item_capacity) return;
  uint kept_count = kept_words[kept_word];
#if !EMIT
  if (j >= kept_count) {
    counts[j] = 0u;
    return;
  }
#else
  if (j >= kept_count) return;
#endif
  uint entry = entries[j];
  SplatRecord r = records[entry];
  ivec4 rect = r.rect;
  uint area = uint((rect.z - rect.x) * (rect.w - rect.y));
  if (area > kTileSplatHugeTiles) {
#if !EMIT
    huge_items[atomicAdd(huge.count, 1u)] = j;
#endif
    return;
  }
  uint first_slot = item_first_slot(j, entry, tile_grid);
  uint n = 0u;
#if EMIT
  uint base = counts[j];
#endif
  for (int ty = rect.y; ty < rect.w; ++ty)
    for (int tx = rect.x; tx < rect.z; ++tx)
      if (splat_covers_tile(r, ivec2(tx, ty))) {
#if EMIT
        if (base + n < key_capacity) {
          keys[base + n] = first_slot + uint(ty * tile_grid.x + tx);
          values[base + n] = entry;
        }
#endif
        ++n;
      }
#if !EMIT
  counts[j] = n;
#endif
}
