// The voxel tile rasterizer's keys (gpu/voxels/gl_voxel_tile_raster.hpp), one invocation an item: the
// j-th voxel of the pass's runs (each run a stretch of an octant's front-to-back order seen in one
// image, the runs one after another: VoxelTileRange). EMIT 0 counts the tiles of its footprint in
// the run's image (voxel_footprint.glsl) whose rays can take the run's octant into counts[j];
// EMIT 1 writes their keys (slot = r * tiles + tile for run r; value = the voxel) from its first
// key, counts[j] after the scan. The stable sort then leaves every slot's voxels in its octant's
// order. A quilt's views: a run per (view, octant in that view), so all views of a pass share one
// count, scan, emit and sort. PLANES 1 (V2LF's planes, all at once, one image): the runs are
// GlVoxelBinning's grouped orders (each octant's order grouped by chunk), the voxel's plane is
// chunk_of[voxel] (plane_capacity or more: not binned, no keys) and the slot
// (plane * run_count + r) * tiles + tile, so each plane's slots are one contiguous run.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/voxels/shaders/voxel_tile_io.h"
#define TILE_KEY_CAPACITY 1  // EMIT 1 writes no key past the capacity (GlTileKeys::scan_to_capacity)
#include "gpu/compute/shaders/tile_key_writer.glsl"
#include "gpu/voxels/shaders/voxel_footprint.glsl"
#include "gpu/voxels/shaders/voxel_tile_view.glsl"

layout(local_size_x = kVoxelTileItemsGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kVoxelBoxesBinding) readonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = kVoxelOrderBinding) readonly buffer Order { uint order[]; };
#if PLANES
layout(std430, binding = kVoxelChunkOfBinding) readonly buffer ChunkOf { uint chunk_of[]; };
uniform uint plane_capacity;
#endif

uniform uint item_count;

void main() {
  uint j = flat_invocation_index();
  if (j >= item_count) return;
  // The run holding item j: the first whose end lies past it.
  int lo = 0, hi = run_count - 1;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (j < runs[mid].end_item) hi = mid; else lo = mid + 1;
  }
  VoxelTileRange run = runs[lo];
  uint begin = lo == 0 ? 0u : runs[lo - 1].end_item;
  uint voxel = order[run.order_offset + (j - begin)];
  uint first_slot = uint(lo);  // in units of whole images' tiles
  TileKeyWriter writer = tile_keys_begin(j);
#if PLANES
  uint plane = chunk_of[voxel];
  if (plane >= plane_capacity) {
    tile_keys_end(writer, j);
    return;
  }
  first_slot += uint(run_count) * plane;
#endif
  VoxelView view = voxel_view(run.image);
  ivec4 footprint =
      voxel_footprint(boxes[voxel], view.world_to_camera, view.position, view.tan_half_fov, view.shift_ndc, image_size);
  if (all(lessThanEqual(footprint.xy, footprint.zw))) {
    ivec2 first = footprint.xy / int(kTileSide), last = footprint.zw / int(kTileSide);
    uint tiles = uint(tile_grid.x * tile_grid.y);
    for (int ty = first.y; ty <= last.y; ++ty)
      for (int tx = first.x; tx <= last.x; ++tx)
        if ((tile_octants(view, ivec2(tx, ty)) & (1u << run.octant)) != 0u)
          tile_keys_add(writer, first_slot * tiles + uint(ty * tile_grid.x + tx), voxel);
  }
  tile_keys_end(writer, j);
}
