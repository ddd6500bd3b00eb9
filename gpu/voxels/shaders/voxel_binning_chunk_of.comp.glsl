// V2LF depth binning, pass 5: the chunk (plane) of every voxel, by voxel index, from the binning's
// sorted order: chunk_of[values[i]] = layers[i] for the binned voxels (sorted positions below
// the binned count), `unbinned` (the table's plane capacity: after every chunk) for the others.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/planes/shaders/plane_table.glsl"

layout(local_size_x = kVoxelBinningGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kSplatValuesBinding) readonly buffer Values { uint values[]; };  // sorted voxel indices
layout(std430, binding = kSplatLayersBinding) readonly buffer Layers { uint layers[]; };  // plane per sorted position
layout(std430, binding = kVoxelChunkOfBinding) writeonly buffer ChunkOf { uint chunk_of[]; };

uniform uint voxel_count;
uniform uint unbinned;

void main() {
  const uint i = flat_invocation_index();
  if (i >= voxel_count) return;
  chunk_of[values[i]] = i < table.splats_binned ? layers[i] : unbinned;
}
