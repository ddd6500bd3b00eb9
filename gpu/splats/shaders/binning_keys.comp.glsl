// G2LF depth binning, pass 1 (Alg. 1 line 1, CulledDepth; render/depth_binning.cpp): the
// Gaussians whose centre lies in the reference frustum (z > 0.2, |x|, |y| <= 1.3 tan(theta'/2) z,
// the rasterizer's guard band) get their reference-camera depth as the sort key (float bits:
// depth > 0.2 orders as the floats), the others 0xFFFFFFFF so they sort after every binned one;
// values are the Gaussian indices. Binned Gaussians are counted in the plane table.
#include "gpu/splats/shaders/frame_io.h"

layout(local_size_x = kBinningKeysGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kScenePositionsBinding) readonly buffer Positions { vec4 positions[]; };  // xyz, opacity
layout(std430, binding = kSplatKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kSplatValuesBinding) writeonly buffer Values { uint values[]; };
layout(std430, binding = kPlaneTableBinding) buffer PlaneTable {
  PlaneTableHeader table;
  PlaneTableEntry plane[];
};

uniform uint gaussian_count;
uniform mat3 world_to_camera;  // the reference camera's
uniform vec3 camera_position;
uniform vec2 limit;            // 1.3 tan(theta'/2), x and y

shared uint group_binned;

void main() {
  if (gl_LocalInvocationIndex == 0u) group_binned = 0u;
  barrier();
  const uint i = flat_invocation_index();
  if (i < gaussian_count) {
    // Camera::to_camera as glm evaluates it (column by column, no fused multiply-add), so the
    // depths and the frustum test agree with the CPU's bit for bit.
    precise const vec3 d = positions[i].xyz - camera_position;
    precise const vec3 t = world_to_camera[0] * d.x + world_to_camera[1] * d.y + world_to_camera[2] * d.z;
    const bool culled = !(t.z > 0.2) || abs(t.x) > limit.x * t.z || abs(t.y) > limit.y * t.z;
    keys[i] = culled ? 0xFFFFFFFFu : floatBitsToUint(t.z);
    values[i] = i;
    if (!culled) atomicAdd(group_binned, 1u);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && group_binned > 0u) atomicAdd(table.splats_binned, group_binned);
}
