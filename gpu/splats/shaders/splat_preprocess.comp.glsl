// Per-Gaussian preprocess of one camera (gpu/splats/gl_splat_preprocess.hpp): the projection
// (splat_project.glsl, the twin of render/preprocess.cpp), then the record, key and value the sort
// and the instanced draw read.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/splat_record.glsl"

layout(local_size_x = kSplatPreprocessGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kScenePositionsBinding) readonly buffer Positions { vec4 positions[]; };  // xyz, opacity
layout(std430, binding = kSceneScalesBinding) readonly buffer Scales { vec4 scales[]; };
layout(std430, binding = kSceneRotationsBinding) readonly buffer Rotations { vec4 rotations[]; };  // w, x, y, z
layout(std430, binding = kSplatRecordsBinding) writeonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kSplatKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kSplatValuesBinding) writeonly buffer Values { uint values[]; };
layout(std430, binding = kSplatDrawBinding) buffer Draw { uint draw_count; uint draw_instances; uint draw_first; uint draw_base; };
// The visible depths' range as float bits (positive floats order as their bits), reset to
// (0xFFFFFFFF, 0) before the pass: the sort's normalised keys (gpu/compute/gl_radix_sort.hpp).
layout(std430, binding = kSplatDepthRangeBinding) buffer DepthRange { uint depth_min_bits; uint depth_max_bits; };

uniform uint gaussian_count;
uniform mat3 world_to_camera;
uniform vec3 camera_position;
uniform vec2 tan_half_fov;
uniform vec2 focal_px;
uniform vec2 shift_ndc;
uniform ivec2 image_size;
uniform ivec2 tile_grid;
uniform float dilation_px2;
uniform float scale_modifier;
uniform vec3 sh_origin;

#include "gpu/splats/shaders/splat_project.glsl"

uint cull(uint i) {
  records[i] = SplatRecord(vec4(0.0), vec4(0.0), vec4(0.0), ivec4(0));
  keys[i] = 0xFFFFFFFFu;
  values[i] = i;
  return 0xFFFFFFFFu;
}

// Gaussian i's record, key and value; returns the key (0xFFFFFFFF: culled).
uint preprocess(uint i) {
  SplatRecord record;
  uint key;
  if (!project_splat(i, record, key)) return cull(i);
  records[i] = record;
  keys[i] = key;
  values[i] = i;
  return key;
}

// The visible count and depth range reduced in the work group first: three global atomics per
// group instead of one per visible Gaussian.
shared uint group_visible, group_min, group_max;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    group_visible = 0u;
    group_min = 0xFFFFFFFFu;
    group_max = 0u;
  }
  barrier();
  uint i = flat_invocation_index();
  if (i < gaussian_count) {
    uint key = preprocess(i);
    if (key != 0xFFFFFFFFu) {
      atomicAdd(group_visible, 1u);
      atomicMin(group_min, key);
      atomicMax(group_max, key);
    }
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u && group_visible > 0u) {
    atomicAdd(draw_instances, group_visible);
    atomicMin(depth_min_bits, group_min);
    atomicMax(depth_max_bits, group_max);
  }
}
