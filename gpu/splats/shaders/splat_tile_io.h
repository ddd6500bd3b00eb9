// The compute tile rasterizer of Gaussians' contract (gpu/splats/gl_splat_tile_raster.hpp;
// gpu/splats/shaders/splat_tile_*.comp.glsl), on top of the generic tile machinery's
// (gpu/compute/shaders/tile_io.h; bindings not named here are its and the splat passes',
// gpu/splats/shaders/frame_io.h). Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_SPLAT_TILE_IO_H
#define LFD_GPU_SHADERS_SPLAT_TILE_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_INT(kTileSplatEntryKeysBinding, 5)  // per (view, Gaussian): its depth key (preprocess)
LFD_IO_INT(kTileSplatEntriesBinding, 7)    // the items: entries (records) front to back
LFD_IO_INT(kTileSplatViewsBinding, 9)      // TileViewCamera per view (preprocess)
LFD_IO_INT(kTileSplatKeptBinding, 11)      // the item count (a uint; the depth sort's kept count)
LFD_IO_INT(kTileSplatLayersBinding, 12)    // planes: the plane of each item (count and emit)
LFD_IO_INT(kTileSplatHugeBinding, 15)      // the huge items: TileHugeList, then their item indices
LFD_IO_INT(kTileSplatTargetImage, 0)       // image unit the compositing writes
// The split of hot tiles (docs/gpu.md "Balancing"), bound in the compositing passes, where the
// key passes' bindings 11 and 15 are free.
LFD_IO_INT(kTileSplatSplitBinding, 11)     // TileSplitList, then the split slots, then the parts
LFD_IO_INT(kTileSplatPartialsBinding, 15)  // per part, per pixel of its tile: vec4(C, T), T < 0: stopped

// An item whose tile rectangle holds more tiles than this has its tiles tested and its keys
// written by a whole work group of kTileSplatHugeGroupSize (one invocation a tile), not by one
// invocation's loop (docs/gpu.md "Balancing").
LFD_IO_UINT(kTileSplatHugeTiles, 32u)
LFD_IO_UINT(kTileSplatHugeGroupSize, 64u)
LFD_IO_UINT(kTileSplatItemsGroupSize, 128u)  // count and emit: one invocation an item

// A slot whose list holds more than the split threshold (GlSplatTileRaster::set_split_keys; default
// kTileSplatSplitKeys) is composited in parts of that many keys by a work group each, from
// T = 1, into partial (C, T); a merge pass then combines them front to back (C = C0 + T0 C1 +
// T0 T1 C2 ...) and replays, pixel by pixel, the one part where the reference's early stop falls.
// At most kTileSplatMaxParts parts a frame: slots beyond them are composited whole.
LFD_IO_UINT(kTileSplatSplitKeys, 2048u)
LFD_IO_UINT(kTileSplatMaxParts, 4096u)
LFD_IO_UINT(kTileSplatSplitGroupSize, 256u)  // the split pass: one invocation a non-empty slot

// The split list's header (std430); kTileSplatMaxParts split slots (uvec4: slot, first key, end
// key, first part) follow from word 12, then kTileSplatMaxParts parts (uvec2: split slot, part;
// 0xFFFFFFFF: none).
struct TileSplitList {
  uint slots LFD_IO_ZERO;  // split slots listed
  uint parts LFD_IO_ZERO;  // parts handed out (may pass kTileSplatMaxParts: those past it are none)
  uint pad0 LFD_IO_ZERO;
  uint pad1 LFD_IO_ZERO;
  uint merge_groups_x LFD_IO_ZERO;  // one work group a split slot (GlTileKeys::write_dispatch)
  uint merge_groups_y LFD_IO_ZERO;
  uint merge_groups_z LFD_IO_ZERO;
  uint pad2 LFD_IO_ZERO;
  uint part_groups_x LFD_IO_ZERO;  // one work group a part
  uint part_groups_y LFD_IO_ZERO;
  uint part_groups_z LFD_IO_ZERO;
  uint pad3 LFD_IO_ZERO;
};
LFD_IO_UINT(kTileSplitListWords, 12u)

// The huge items' list header (std430); the item indices follow from word 8.
struct TileHugeList {
  uint count LFD_IO_ZERO;
  uint pad0 LFD_IO_ZERO;
  uint pad1 LFD_IO_ZERO;
  uint pad2 LFD_IO_ZERO;
  uint groups_x LFD_IO_ZERO;  // one work group a huge item (gpu::GlTileKeys::write_dispatch)
  uint groups_y LFD_IO_ZERO;
  uint groups_z LFD_IO_ZERO;
  uint pad3 LFD_IO_ZERO;
};
LFD_IO_UINT(kTileHugeListWords, 8u)

// One view's camera for the all-views preprocess (std430, 112 bytes; the uniforms of the
// per-view preprocess, gpu/splats/gl_splat_preprocess.cpp).
struct TileViewCamera {
  float world_to_camera[12] LFD_IO_ZERO;  // mat3 columns, each padded to 4 floats
  float position[4] LFD_IO_ZERO;
  float sh_origin[4] LFD_IO_ZERO;
  float tan_half_fov[2] LFD_IO_ZERO;
  float focal_px[2] LFD_IO_ZERO;
  float shift_ndc[2] LFD_IO_ZERO;
  float pad[2] LFD_IO_ZERO;
};

LFD_IO_END

#endif
