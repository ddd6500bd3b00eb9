// The compute tile rasterizer of voxels' contract (gpu/gl_voxel_tile_raster.hpp;
// gpu/shaders/voxel_tile_*.comp.glsl), on the generic tile machinery's (gpu/shaders/tile_io.h:
// keys, values, ranges, work list) and the voxel scene's bindings (gpu/shaders/frame_io.h:
// boxes, densities, orders, SH). Read by C++ and GLSL (gpu/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_VOXEL_TILE_IO_H
#define LFD_GPU_SHADERS_VOXEL_TILE_IO_H
#include "gpu/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_INT(kVoxelTileTargetImage, 0)         // image unit of the (C, T) target (rgba32f), read and written
LFD_IO_UINT(kVoxelTileItemsGroupSize, 128u)  // count and emit: one invocation an item (a voxel of an octant's order)
// Slots: ((image * octants drawn + octant's index) * tiles_per_image + tile); a tile whose rays
// take several octants has a list per octant, each in that octant's front-to-back order, and a
// pixel reads its own ray's.

LFD_IO_END

#endif
