// V2LF depth binning, pass 1 (voxel::bin_voxels_by_depth's cull and depth; the twin of
// binning_keys.comp.glsl for voxels): a voxel with any corner in front of the reference camera
// (centre depth + half its depth extent > 0) gets its centre's reference depth as the sort key
// (depth_key: a centre may lie behind the camera), the others 0xFFFFFFFF; values are the voxel
// indices. Binned voxels are counted in the plane table. The depths are the CPU's bit for bit:
// the centre as VoxelScene::voxel_center (min + edge / 2), Camera::to_camera as glm evaluates it
// (no fused multiply-add), the half extent as (edge / 2) (|f.x| + |f.y| + |f.z|).
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/depth_key.glsl"

layout(local_size_x = kVoxelBinningGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kVoxelBoxesBinding) readonly buffer Boxes { vec4 boxes[]; };  // min xyz, edge
layout(std430, binding = kSplatKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kSplatValuesBinding) writeonly buffer Values { uint values[]; };
layout(std430, binding = kPlaneTableBinding) buffer PlaneTable {
  PlaneTableHeader table;  // here splats_binned counts the voxels binned
  PlaneTableEntry plane[];
};

uniform uint voxel_count;
uniform mat3 world_to_camera;  // the reference camera's
uniform vec3 camera_position;
uniform float extent_factor;   // |f.x| + |f.y| + |f.z| of the camera's forward axis f (CPU-summed)

shared uint group_binned;

void main() {
  if (gl_LocalInvocationIndex == 0u) group_binned = 0u;
  barrier();
  const uint i = flat_invocation_index();
  if (i < voxel_count) {
    const vec4 box = boxes[i];
    precise const vec3 centre = box.xyz + 0.5 * box.w;
    precise const vec3 d = centre - camera_position;
    precise const vec3 t = world_to_camera[0] * d.x + world_to_camera[1] * d.y + world_to_camera[2] * d.z;
    precise const float half_extent = (0.5 * box.w) * extent_factor;
    precise const float near_corner = t.z + half_extent;
    const bool binned = near_corner > 0.0;
    keys[i] = binned ? depth_key(t.z) : 0xFFFFFFFFu;
    values[i] = i;
    if (binned) atomicAdd(group_binned, 1u);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && group_binned > 0u) atomicAdd(table.splats_binned, group_binned);
}
