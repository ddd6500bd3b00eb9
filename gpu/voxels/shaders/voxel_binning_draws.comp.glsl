// V2LF depth binning, pass 7: the indirect draws of the planes, one per (plane k, octant o) at
// command 8 k + o (gpu/voxels/gl_voxel_raster.hpp, draw_indirect): a 4-vertex strip instanced once per
// voxel of chunk k in octant o's order; the base instance is where those voxels begin in the
// grouped orders (the vertex shader reads it: gl_InstanceID does not include it). Planes past the
// frame's plane count and octants not in view draw nothing. After the draws, per plane k at
// entry 8 max_planes + k, the indirect dispatch of its filter and convert passes: the plane's
// work groups, none past the plane count (so those planes cost no GPU work).
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/planes/shaders/plane_table.glsl"

layout(local_size_x = kVoxelDrawsGroupSize) in;

layout(std430, binding = kVoxelDrawsBinding) writeonly buffer Draws { uvec4 draws[]; };  // count, instances, first, base instance

uniform uint voxel_count;
uniform uint max_planes;
uniform int slot_of_octant[kVoxelOctants];  // -1: not in view
uniform uvec2 plane_groups;     // work groups of a per-plane pass (16 x 8 texels each)

void main() {
  const uint c = gl_GlobalInvocationID.x;
  if (c >= kVoxelOctants * max_planes) return;
  const uint k = c / kVoxelOctants, octant = c % kVoxelOctants;
  if (octant == 0u) draws[kVoxelOctants * max_planes + k] = k < table.plane_count ? uvec4(plane_groups, 1u, 0u) : uvec4(0u);
  const int slot = slot_of_octant[octant];
  if (k >= table.plane_count || slot < 0) {
    draws[c] = uvec4(4u, 0u, 0u, 0u);
    return;
  }
  const uint begin = plane[k].begin;
  draws[c] = uvec4(4u, plane[k + 1u].begin - begin, 0u, uint(slot) * voxel_count + begin);
}
