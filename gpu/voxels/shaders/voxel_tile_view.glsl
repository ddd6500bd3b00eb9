// The views and runs of the voxel tile rasterizer's passes (gpu/voxels/gl_voxel_tile_raster.hpp;
// VoxelTileView and VoxelTileRange in voxel_tile_io.h), and the octants a tile's rays take (the
// world direction is linear in the pixel position, so the tile's corner pixels bound its signs
// per axis, as gpu::octants_in_view does per image). Every image of a pass has one size.
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/voxels/shaders/voxel_tile_io.h"

layout(std430, binding = kVoxelTileViewsBinding) readonly buffer Views { VoxelTileView views[]; };
layout(std430, binding = kVoxelTileRangesBinding) readonly buffer Runs { VoxelTileRange runs[]; };

uniform ivec2 image_size;
uniform ivec2 tile_grid;
uniform int run_count;  // the runs of the pass (per plane, for V2LF's planes)

struct VoxelView {
  mat3 world_to_camera;
  vec3 position;
  vec3 sh_origin;
  vec2 tan_half_fov;
  vec2 shift_ndc;
};

VoxelView voxel_view(uint image) {
  VoxelTileView c = views[image];
  VoxelView v;
  v.world_to_camera = mat3(vec3(c.world_to_camera[0], c.world_to_camera[1], c.world_to_camera[2]),
                           vec3(c.world_to_camera[4], c.world_to_camera[5], c.world_to_camera[6]),
                           vec3(c.world_to_camera[8], c.world_to_camera[9], c.world_to_camera[10]));
  v.position = vec3(c.position[0], c.position[1], c.position[2]);
  v.sh_origin = vec3(c.sh_origin[0], c.sh_origin[1], c.sh_origin[2]);
  v.tan_half_fov = vec2(c.tan_half_fov[0], c.tan_half_fov[1]);
  v.shift_ndc = vec2(c.shift_ndc[0], c.shift_ndc[1]);
  return v;
}

uint tile_octants(VoxelView v, ivec2 tile) {
  ivec2 first = tile * int(kTileSide), last = min(first + int(kTileSide) - 1, image_size - 1);
  uint negative = 0u, positive = 0u;  // per axis (bit 2 = x, 1 = y, 0 = z): a corner ray has that sign
  for (int c = 0; c < 4; ++c) {
    vec2 pixel = vec2((c & 1) != 0 ? last.x : first.x, (c & 2) != 0 ? last.y : first.y);
    vec2 ndc = (2.0 * pixel + 1.0) / vec2(image_size) - 1.0;
    vec3 d = transpose(v.world_to_camera) * vec3((ndc - v.shift_ndc) * v.tan_half_fov, 1.0);
    negative |= (d.x < 0.0 ? 4u : 0u) | (d.y < 0.0 ? 2u : 0u) | (d.z < 0.0 ? 1u : 0u);
    positive |= (d.x < 0.0 ? 0u : 4u) | (d.y < 0.0 ? 0u : 2u) | (d.z < 0.0 ? 0u : 1u);
  }
  uint mask = 0u;
  for (uint o = 0u; o < 8u; ++o) {
    uint wants_negative = o, wants_positive = ~o & 7u;
    if ((wants_negative & ~negative) == 0u && (wants_positive & ~positive) == 0u) mask |= 1u << o;
  }
  return mask;
}
