// One quad per voxel of an octant's front-to-back order (instanced, a 4-vertex strip): the
// GLSL twin of voxel/voxel_rasterizer.cpp's stages 1 and 3. The quad covers every pixel whose
// centre ray can meet the box: the projected corners' bounding box, a pixel wider for rounding;
// the whole image when a corner lies behind the camera plane (the fragment's slab test sorts
// out the rays, as the CPU's tile rectangle does); nothing when all 8 do. The voxel's colour is
// its SH seen from `sh_origin` towards the voxel centre, once per voxel per view.
#include "gpu/shaders/frame_io.h"
#include "gpu/shaders/sh_color.glsl"

layout(std430, binding = kVoxelBoxesBinding) readonly buffer Boxes { vec4 boxes[]; };  // min xyz, edge
layout(std430, binding = kVoxelOrderBinding) readonly buffer Order { uint order[]; };
// V2LF's indirect draws (gpu/gl_voxel_binning.hpp): count, instances, first, base instance.
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
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  int behind = 0;
  for (int c = 0; c < 8; ++c) {
    vec3 corner = box.xyz + box.w * vec3(float((c >> 2) & 1), float((c >> 1) & 1), float(c & 1));
    vec3 p = world_to_camera * (corner - camera_position);
    if (p.z <= 1e-6) {
      ++behind;
      continue;
    }
    // Pixel coordinates with centres at integers, row 0 = top (render::Camera::project_px).
    vec2 ndc = p.xy / (p.z * tan_half_fov) + shift_ndc;
    vec2 px = ((ndc + 1.0) * vec2(image_size) - 1.0) * 0.5;
    lo = min(lo, px);
    hi = max(hi, px);
  }
  ivec2 first = ivec2(0), last = image_size - 1;
  if (behind == 8) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
    return;
  }
  if (behind == 0) {
    // Clamped as floats first: a huge extent must not overflow the conversion to int.
    vec2 limit_lo = vec2(-1.0), limit_hi = vec2(image_size);
    first = max(first, ivec2(clamp(floor(lo) - 1.0, limit_lo, limit_hi)));
    last = min(last, ivec2(clamp(ceil(hi) + 1.0, limit_lo, limit_hi)));
    if (any(greaterThan(first, last))) {
      gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
      return;
    }
  }
  v_color = sh_color(voxel, normalize(box.xyz + 0.5 * box.w - sh_origin));
  // Pixel edges first .. last + 1; GL's y runs up, so image row y lies at window row H - 1 - y.
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  vec2 edge = mix(vec2(first), vec2(last + 1), corner);
  gl_Position = vec4(edge.x / float(image_size.x) * 2.0 - 1.0, 1.0 - edge.y / float(image_size.y) * 2.0, 0.0, 1.0);
}
