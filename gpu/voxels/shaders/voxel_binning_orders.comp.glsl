// V2LF depth binning, pass 6: the keys that group an octant's front-to-back order
// (gpu/voxels/gl_voxel_scene.hpp) by chunk. For position j of that octant's order: value = the voxel,
// key = its chunk (the plane capacity for the unbinned). A stable sort of these keys lists every
// chunk's voxels in the octant's order, chunk after chunk, the unbinned last: chunk k's begin at
// the chunk's first sorted position (the plane table's begin: every order holds the same voxels
// per chunk). One octant at a time: the keys need only the chunk's bits (one radix pass up to
// 255 planes).
#include "gpu/splats/shaders/frame_io.h"

layout(local_size_x = kVoxelBinningGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kVoxelOrderBinding) readonly buffer Order { uint order[]; };  // eight orders of n
layout(std430, binding = kSplatKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kSplatValuesBinding) writeonly buffer Values { uint values[]; };
layout(std430, binding = kVoxelChunkOfBinding) readonly buffer ChunkOf { uint chunk_of[]; };

uniform uint voxel_count;
uniform uint octant;

void main() {
  const uint j = flat_invocation_index();
  if (j >= voxel_count) return;
  const uint voxel = order[octant * voxel_count + j];
  keys[j] = chunk_of[voxel];
  values[j] = voxel;
}
