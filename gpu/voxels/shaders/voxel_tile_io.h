// The compute tile rasterizer of voxels' contract (gpu/voxels/gl_voxel_tile_raster.hpp;
// gpu/voxels/shaders/voxel_tile_*.comp.glsl), on the generic tile machinery's (gpu/compute/shaders/tile_io.h:
// keys, values, ranges, work list) and the voxel scene's bindings (gpu/splats/shaders/frame_io.h:
// boxes, densities, orders, SH). Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_VOXEL_TILE_IO_H
#define LFD_GPU_SHADERS_VOXEL_TILE_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_INT(kVoxelTileTargetImage, 0)         // image unit of the (C, T) target (rgba32f), read and written
LFD_IO_INT(kVoxelTileRangesBinding, 15)      // VoxelTileRange per run of items (keys and march)
LFD_IO_INT(kVoxelTileViewsBinding, 7)        // VoxelTileView per image (keys and march)
LFD_IO_UINT(kVoxelTileItemsGroupSize, 128u)  // count and emit: one invocation an item (a voxel of an octant's order)

// A run of items: voxels order[order_offset ..] of `octant`'s front-to-back order, seen in image
// `image`; the runs lie one after another (run r ends before item end_item). The slot of a key
// is ((plane * runs) + r) * tiles_per_image + tile (plane 0 for a quilt's views), so a tile whose
// rays take several octants has a list per octant, each in that octant's order, and a pixel reads
// its own ray's; a quilt's views are runs too (one per octant in each view), so every view of a
// pass goes in one sort and one dispatch. std430.
struct VoxelTileRange {
  uint end_item LFD_IO_ZERO;
  uint order_offset LFD_IO_ZERO;
  uint octant LFD_IO_ZERO;
  uint image LFD_IO_ZERO;  // the view (its camera in the views buffer, its cell in the target)
};

// One image's camera (render::Camera; all images of a pass have one size) and the point its SH
// colours are seen from. std430, 96 bytes.
struct VoxelTileView {
  float world_to_camera[12] LFD_IO_ZERO;  // mat3 columns, each padded to 4 floats
  float position[4] LFD_IO_ZERO;          // xyz
  float sh_origin[4] LFD_IO_ZERO;         // xyz
  float tan_half_fov[2] LFD_IO_ZERO;
  float shift_ndc[2] LFD_IO_ZERO;
};

LFD_IO_END

#endif
