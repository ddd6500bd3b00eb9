// One quad per voxel of an octant's front-to-back order (instanced, a 4-vertex strip): the
// GLSL twin of voxel/voxel_rasterizer.cpp's stages 1 and 3. The quad covers the voxel's
// footprint (gpu/voxels/shaders/voxel_footprint.glsl); nothing when it is empty. The voxel's colour is
// its SH seen from `sh_origin` towards the voxel centre, once per voxel per view.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/sh_color.glsl"
#include "gpu/voxels/shaders/voxel_footprint.glsl"

layout(std430, binding = kVoxelBoxesBinding) readonly buffer Boxes { vec4 boxes[]; };  // min xyz, edge
layout(std430, binding = kVoxelOrderBinding) readonly buffer Order { uint order[]; };
// V2LF's indirect draws (gpu/voxels/gl_voxel_binning.hpp): count, instances, first, base instance.
layout(std430, binding = kVoxelDrawsBinding) readonly buffer Draws { uvec4 draws[]; };

uniform uint order_offset;  // first entry of this draw's order
uniform int draw_command;   // >= 0: an indirect draw's, whose base instance is added to order_offset
uniform mat3 world_to_camera;
uniform vec3 camera_position;
uniform vec2 tan_half_fov;
uniform vec2 shift_ndc;
uniform ivec2 image_size;
uniform vec3 sh_origin;

flat out uint v_voxel;
flat out vec3 v_color;

void main() {
  const uint draw_first = order_offset + (draw_command >= 0 ? draws[draw_command].w : 0u);
  uint voxel = order[draw_first + uint(gl_InstanceID)];
  v_voxel = voxel;
  vec4 box = boxes[voxel];
  ivec4 footprint = voxel_footprint(box, world_to_camera, camera_position, tan_half_fov, shift_ndc, image_size);
  ivec2 first = footprint.xy, last = footprint.zw;
  if (any(greaterThan(first, last))) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
    return;
  }
  v_color = sh_color(voxel, normalize(box.xyz + 0.5 * box.w - sh_origin));
  // Pixel edges first .. last + 1; GL's y runs up, so image row y lies at window row H - 1 - y.
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  vec2 edge = mix(vec2(first), vec2(last + 1), corner);
  gl_Position = vec4(edge.x / float(image_size.x) * 2.0 - 1.0, 1.0 - edge.y / float(image_size.y) * 2.0, 0.0, 1.0);
}
