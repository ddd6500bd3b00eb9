// The tile machinery's contract (gpu/compute/gl_tile_keys.hpp; gpu/compute/shaders/tile_scan_*.comp.glsl,
// tile_ranges.comp.glsl): generic over what is drawn (Gaussians, voxels) and over what an image
// is (a view of a quilt, a plane). Items (a primitive seen in one image), in the order their
// lists must keep (front to back), each cover some of the image's 16 x 16 tiles; a client pass
// counts each item's tiles into `counts`, the scan turns them into write offsets, a client pass
// writes one key per (item, tile) (the slot: image * tiles_per_image + tile) with the item as
// value, the stable radix sort orders the keys by slot keeping the items' order inside a slot,
// and the ranges pass finds each slot's run of sorted keys and lists the non-empty slots for an
// indirect dispatch (docs/gpu.md "The compute tile rasterizer"). Read by C++ and GLSL
// (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_TILE_IO_H
#define LFD_GPU_SHADERS_TILE_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

// Storage buffers (a pass binds what it reads before it runs; the scene keeps 0-3, records 4).
LFD_IO_INT(kTileKeysBinding, 5)       // the slot of each (item, tile), sorted
LFD_IO_INT(kTileValuesBinding, 6)     // its item
LFD_IO_INT(kTileCountsBinding, 8)     // per item: its tile count, scanned in place into its first key
LFD_IO_INT(kTileBlockSumsBinding, 9)  // the scan's per-block totals, scanned in place
LFD_IO_INT(kTileStateBinding, 10)     // TileState
LFD_IO_INT(kTileRangesBinding, 12)    // per slot: uvec2 (first key, end key), (0, 0) when empty
LFD_IO_INT(kTileWorkBinding, 13)      // the non-empty slots, in no particular order
LFD_IO_INT(kTileItemsBinding, 14)     // the items counted (a uint, written by the client)

// The scan: a block is kTileScanGroupSize invocations of kTileScanPerInvocation items; one
// work group scans every block total (kTileScanMaxBlocks), so it covers
// kTileScanGroupSize * kTileScanPerInvocation * kTileScanMaxBlocks = 2^30 items.
LFD_IO_UINT(kTileScanGroupSize, 256u)
LFD_IO_UINT(kTileScanPerInvocation, 4u)
LFD_IO_UINT(kTileScanBlockItems, 1024u)
LFD_IO_UINT(kTileScanMaxBlocks, 1048576u)
LFD_IO_UINT(kTileRangesGroupSize, 256u)
LFD_IO_UINT(kTileDispatchGroupSize, 1u)  // tile_dispatch: one invocation writes the command
// 16 x 16 pixels a tile (render::kTileSize), one invocation each in the compositing passes.
LFD_IO_UINT(kTileSide, 16u)
LFD_IO_UINT(kTilePixels, 256u)

// What the scan and the ranges pass leave for the CPU and for indirect dispatches (std430).
struct TileState {
  uint keys LFD_IO_ZERO;       // total keys: the scan's sum of the counts
  uint work_count LFD_IO_ZERO; // non-empty slots listed in the work buffer
  uint pad0 LFD_IO_ZERO;
  uint pad1 LFD_IO_ZERO;
  uint groups_x LFD_IO_ZERO;   // DispatchIndirectCommand over the non-empty slots: one work group
  uint groups_y LFD_IO_ZERO;   // a slot, groups_x = min(count, 65535) and groups_y rows of it
  uint groups_z LFD_IO_ZERO;
  uint pad2 LFD_IO_ZERO;
};

LFD_IO_END

#endif
