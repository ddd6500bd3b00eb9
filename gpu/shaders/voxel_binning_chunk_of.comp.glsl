// V2LF depth binning, pass 5: the chunk (plane) of every voxel, by voxel index, from the binning's
// sorted order: chunk_of[values[i]] = layers[i] for the binned voxels (sorted positions below
// the binned count), `unbinned` (the table's plane capacity: after every chunk) for the others.
layout(local_size_x = 256) in;

layout(std430, binding = 6) readonly buffer Values { uint values[]; };  // sorted voxel indices
layout(std430, binding = 8) readonly buffer Layers { uint layers[]; };  // plane per sorted position
layout(std430, binding = 9) readonly buffer PlaneTable {
  uint plane_count;
  uint splats_binned;
};
layout(std430, binding = 11) writeonly buffer ChunkOf { uint chunk_of[]; };

uniform uint voxel_count;
uniform uint unbinned;

void main() {
  const uint i = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (i >= voxel_count) return;
  chunk_of[values[i]] = i < splats_binned ? layers[i] : unbinned;
}
