// The compute tile rasterizer's keys (gpu/splats/gl_splat_tile_raster.hpp), one invocation an item (a splat in
// one image, front to back): EMIT 0 counts the tiles it covers (splat_tile_cover.glsl) into
// counts[j], EMIT 1 writes its keys (slot = image * tiles + tile, value = its record) from its
// first key, counts[j] after the scan. Items with more than kTileSplatHugeTiles tiles in their
// rectangle are listed for splat_tile_huge.comp.glsl instead. PLANES 0: the image is the view,
// entry / gaussian_count; PLANES 1: the item's plane, layers[j].
#include "gpu/splats/shaders/splat_record.glsl"
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/splats/shaders/splat_tile_io.h"
#include "gpu/splats/shaders/splat_tile_cover.glsl"
#include "gpu/splats/shaders/splat_tile_item.glsl"
#include "gpu/splats/shaders/frame_io.h"
#define TILE_KEY_CAPACITY 1
#include "gpu/compute/shaders/tile_key_writer.glsl"

layout(local_size_x = kTileSplatItemsGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kSplatRecordsBinding) readonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kTileSplatEntriesBinding) readonly buffer Entries { uint entries[]; };
layout(std430, binding = kTileSplatKeptBinding) readonly buffer Kept { uint kept_words[]; };
#if !EMIT
layout(std430, binding = kTileSplatHugeBinding) buffer Huge { TileHugeList huge; uint huge_items[]; };
#endif

uniform uint item_capacity;  // items dispatched; those from the kept count on have no keys
uniform uint kept_word;      // the kept count's index in kept_words (the sort's params or a draw)
uniform ivec2 tile_grid;

void main() {
  uint j = flat_invocation_index();
  if (j >= item_capacity) return;
  uint kept_count = kept_words[kept_word];
  if (j >= kept_count) {
    tile_keys_end(tile_keys_begin(j), j);  // no keys (EMIT 0 writes its count, 0)
    return;
  }
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
  TileKeyWriter w = tile_keys_begin(j);
  for (int ty = rect.y; ty < rect.w; ++ty)
    for (int tx = rect.x; tx < rect.z; ++tx)
      if (splat_covers_tile(r, ivec2(tx, ty)))
        tile_keys_add(w, first_slot + uint(ty * tile_grid.x + tx), entry);
  tile_keys_end(w, j);
}
