// SVRaster's per-pixel rule for one voxel (voxel/voxel_rasterizer.cpp voxel_tau): the pixel's
// ray (centre at integer coordinates, row 0 = top, the CPU's pixel_ray), a slab test against
// the box, K midpoint samples of the trilinear raw density through exp_linear_11,
// tau = sum 100 dt sigma, alpha = min(0.99999, 1 - exp(-tau)), skip alpha < 1e-5. Rays of
// another octant than this pass's are left to that octant's pass (its order is theirs).
// Output premultiplied (c alpha, alpha): the splat raster's blend then gives C += c alpha T,
// T *= 1 - alpha front to back (gpu/gl_splat_raster.hpp).
#include "gpu/shaders/frame_io.h"

layout(std430, binding = kVoxelBoxesBinding) readonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = kVoxelDensitiesBinding) readonly buffer Densities { vec4 densities[]; };  // corners 0-3, 4-7

uniform mat3 world_to_camera;
uniform vec3 camera_position;
uniform vec2 tan_half_fov;
uniform vec2 shift_ndc;
uniform ivec2 image_size;
uniform vec2 viewport_origin;  // window coordinates of the view's bottom-left corner
uniform int octant;            // this pass's: bit 2 = x, 1 = y, 0 = z negative
uniform int samples_per_voxel;

flat in uint v_voxel;
flat in vec3 v_color;

layout(location = 0) out vec4 out_color;

const float kStepScale = 100.0;
const float kMaxAlpha = 0.99999;
const float kMinAlpha = 1e-5;

// scene/voxel_scene.cpp exp_linear_11.
float exp_linear_11(float x) { return x > 1.1 ? x : exp(x / 1.1 - 1.0 + log(1.1)); }

float trilinear(vec4 c0123, vec4 c4567, vec3 t) {
  // Corner i at (x, y, z) = bits (2, 1, 0): along z first, then y, then x.
  vec4 z0 = vec4(c0123.x, c0123.z, c4567.x, c4567.z), z1 = vec4(c0123.y, c0123.w, c4567.y, c4567.w);
  vec4 along_z = mix(z0, z1, t.z);             // (x0y0, x0y1, x1y0, x1y1)
  vec2 along_y = mix(along_z.xz, along_z.yw, t.y);  // (x0, x1)
  return mix(along_y.x, along_y.y, t.x);
}

void main() {
  vec2 window = gl_FragCoord.xy - viewport_origin;  // pixel centres at .5
  vec2 pixel = vec2(window.x - 0.5, float(image_size.y) - window.y - 0.5);
  vec2 ndc = (2.0 * pixel + 1.0) / vec2(image_size) - 1.0;
  vec3 d_cam = vec3((ndc - shift_ndc) * tan_half_fov, 1.0);
  vec3 d = normalize(transpose(world_to_camera) * d_cam);
  int ray_octant = (d.x < 0.0 ? 4 : 0) | (d.y < 0.0 ? 2 : 0) | (d.z < 0.0 ? 1 : 0);
  if (ray_octant != octant) discard;

  vec4 box = boxes[v_voxel];
  vec3 inv = 1.0 / d;
  vec3 ta = (box.xyz - camera_position) * inv, tb = (box.xyz + box.w - camera_position) * inv;
  vec3 tmin = min(ta, tb), tmax = max(ta, tb);
  float t_in = max(max(tmin.x, tmin.y), max(tmin.z, 0.0));
  float t_out = min(min(tmax.x, tmax.y), tmax.z);
  if (!(t_out > t_in)) discard;
  float dt = (t_out - t_in) / float(samples_per_voxel);
  vec4 c0123 = densities[2u * v_voxel], c4567 = densities[2u * v_voxel + 1u];
  float tau = 0.0;
  for (int s = 0; s < samples_per_voxel; ++s) {
    vec3 p = camera_position + (t_in + (float(s) + 0.5) * dt) * d;
    vec3 local = clamp((p - box.xyz) / box.w, 0.0, 1.0);
    tau += kStepScale * dt * exp_linear_11(trilinear(c0123, c4567, local));
  }
  float alpha = min(kMaxAlpha, 1.0 - exp(-tau));
  if (alpha < kMinAlpha) discard;
  out_color = vec4(v_color * alpha, alpha);
}
