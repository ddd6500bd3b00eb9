// V2LF depth binning, pass 6: the keys that group each octant's front-to-back order
// (gpu/gl_voxel_scene.hpp) by chunk. For slot s (the s-th octant in view) and position j of that
// octant's order: value = the voxel, key = (s << chunk_bits) | its chunk. A stable sort of these
// keys lists, per slot, every chunk's voxels in the octant's order, chunk after chunk, the
// unbinned last: slot s's entries are [s n, (s + 1) n), chunk k's begin at s n + the chunk's
// first sorted position (the plane table's begin: every order holds the same voxels per chunk).
layout(local_size_x = 256) in;

layout(std430, binding = 2) readonly buffer Order { uint order[]; };  // eight orders of n
layout(std430, binding = 5) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = 6) writeonly buffer Values { uint values[]; };
layout(std430, binding = 11) readonly buffer ChunkOf { uint chunk_of[]; };

uniform uint voxel_count;
uniform uint slots;      // octants in view
uniform int octant_of_slot[8];
uniform uint chunk_bits;

void main() {
  const uint j = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (j >= voxel_count * slots) return;
  const uint s = j / voxel_count, within = j % voxel_count;
  const uint voxel = order[uint(octant_of_slot[s]) * voxel_count + within];
  keys[j] = (s << chunk_bits) | chunk_of[voxel];
  values[j] = voxel;
}
