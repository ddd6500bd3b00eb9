// The huge items' keys (gpu/splats/gl_splat_tile_raster.hpp; docs/gpu.md "Balancing"): one work group an item
// listed by splat_tile_keys.comp.glsl, one invocation a tile of its rectangle, so a splat that
// covers the whole image costs one group's few steps, not one invocation's loop over every tile.
// EMIT 0 counts the tiles it covers into counts[j]; EMIT 1 writes its keys from its first key (in
// no particular order inside the item: they differ in slot, which the sort orders).
#include "gpu/splats/shaders/splat_record.glsl"
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/splats/shaders/splat_tile_io.h"
#include "gpu/splats/shaders/splat_tile_cover.glsl"
#include "gpu/splats/shaders/splat_tile_item.glsl"
#include "gpu/splats/shaders/frame_io.h"

layout(local_size_x = kTileSplatHugeGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kSplatRecordsBinding) readonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kTileSplatEntriesBinding) readonly buffer Entries { uint entries[]; };
layout(std430, binding = kTileSplatHugeBinding) readonly buffer Huge { TileHugeList huge; uint huge_items[]; };
layout(std430, binding = kTileCountsBinding) buffer Counts { uint counts[]; };
#if EMIT
layout(std430, binding = kTileKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kTileValuesBinding) writeonly buffer Values { uint values[]; };
#endif

uniform ivec2 tile_grid;
#if EMIT
uniform uint key_capacity;  // keys the buffers hold (GlTileKeys::scan_to_capacity): none written past it
#endif

shared uint covered;

void main() {
  uint h = flat_group_index();
  if (h >= huge.count) return;
  uint j = huge_items[h];
  uint entry = entries[j];
  SplatRecord r = records[entry];
  ivec4 rect = r.rect;
  int width = rect.z - rect.x;
  int area = width * (rect.w - rect.y);
  uint first_slot = item_first_slot(j, entry, tile_grid);
  if (gl_LocalInvocationIndex == 0u) covered = 0u;
  barrier();
#if EMIT
  uint base = counts[j];
#endif
  for (int t = int(gl_LocalInvocationIndex); t < area; t += int(kTileSplatHugeGroupSize)) {
    ivec2 tile = ivec2(rect.x + t % width, rect.y + t / width);
    if (splat_covers_tile(r, tile)) {
      uint k = atomicAdd(covered, 1u);
#if EMIT
      if (base + k < key_capacity) {
        keys[base + k] = first_slot + uint(tile.y * tile_grid.x + tile.x);
        values[base + k] = entry;
      }
#endif
    }
  }
#if !EMIT
  barrier();
  if (gl_LocalInvocationIndex == 0u) counts[j] = covered;
#endif
}
