// The voxel tile rasterizer's keys (gpu/gl_voxel_tile_raster.hpp), one invocation an item: the
// j-th voxel of the items' octant ranges (each range a run of an octant's front-to-back order, the
// ranges one after another). EMIT 0 counts the tiles of its footprint (voxel_footprint.glsl) whose
// rays can take its range's octant into counts[j]; EMIT 1 writes their keys (slot = r * tiles +
// tile for range r, one range per octant drawn; value = the voxel) from its first key, counts[j]
// after the scan. The stable sort then leaves every slot's voxels in its octant's order. PLANES 1
// (V2LF's planes, all at once): the ranges are GlVoxelBinning's grouped orders (each octant's
// order grouped by chunk), the voxel's plane is chunk_of[voxel] (plane_capacity or more: not
// binned, no keys) and the slot (plane * range_count + r) * tiles + tile, so each plane's slots
// are one contiguous run.
#include "gpu/shaders/frame_io.h"
#include "gpu/shaders/tile_io.h"
#include "gpu/shaders/voxel_tile_io.h"
#include "gpu/shaders/voxel_footprint.glsl"
#include "gpu/shaders/voxel_tile_view.glsl"

layout(local_size_x = kVoxelTileItemsGroupSize) in;

layout(std430, binding = kVoxelBoxesBinding) readonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = kVoxelOrderBinding) readonly buffer Order { uint order[]; };
#if PLANES
layout(std430, binding = kVoxelChunkOfBinding) readonly buffer ChunkOf { uint chunk_of[]; };
uniform uint plane_capacity;
#endif
#if EMIT
layout(std430, binding = kTileCountsBinding) readonly buffer Counts { uint counts[]; };
layout(std430, binding = kTileKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kTileValuesBinding) writeonly buffer Values { uint values[]; };
#else
layout(std430, binding = kTileCountsBinding) writeonly buffer Counts { uint counts[]; };
#endif

uniform uint item_count;
uniform int range_count;             // ranges in use (one per octant drawn)
uniform uint range_end_item[8];      // items before the end of range r
uniform uint range_offset[8];        // its first entry in `order`
uniform int range_octant[8];

void main() {
  uint j = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (j >= item_count) return;
  int r = 0;
  while (r + 1 < range_count && j >= range_end_item[r]) ++r;
  uint begin = r == 0 ? 0u : range_end_item[r - 1];
  uint voxel = order[range_offset[r] + (j - begin)];
  uint octant = uint(range_octant[r]);
  uint first_slot = uint(r);  // in units of whole images' tiles
#if PLANES
  uint plane = chunk_of[voxel];
  if (plane >= plane_capacity) {
#if !EMIT
    counts[j] = 0u;
#endif
    return;
  }
  first_slot += uint(range_count) * plane;
#endif
  ivec4 footprint = voxel_footprint(boxes[voxel], world_to_camera, camera_position, tan_half_fov, shift_ndc, image_size);
  uint n = 0u;
#if EMIT
  uint base = counts[j];
#endif
  if (all(lessThanEqual(footprint.xy, footprint.zw))) {
    ivec2 first = footprint.xy / int(kTileSide), last = footprint.zw / int(kTileSide);
    uint tiles = uint(tile_grid.x * tile_grid.y);
    for (int ty = first.y; ty <= last.y; ++ty)
      for (int tx = first.x; tx <= last.x; ++tx)
        if ((tile_octants(ivec2(tx, ty)) & (1u << octant)) != 0u) {
#if EMIT
          keys[base + n] = first_slot * tiles + uint(ty * tile_grid.x + tx);
          values[base + n] = voxel;
#endif
          ++n;
        }
  }
#if !EMIT
  counts[j] = n;
#endif
}
