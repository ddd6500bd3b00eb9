// SVRaster's per-pixel rule for one voxel (gpu/voxels/shaders/voxel_ray.glsl, the CPU's voxel_tau), one
// fragment per (voxel, pixel); skip alpha < 1e-5. Rays of another octant than this pass's are left
// to that octant's pass (its order is theirs). Output premultiplied (c alpha, alpha): the splat
// raster's blend then gives C += c alpha T, T *= 1 - alpha front to back (gpu/splats/gl_splat_raster.hpp).
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/voxels/shaders/voxel_ray.glsl"

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

void main() {
  vec2 window = gl_FragCoord.xy - viewport_origin;  // pixel centres at .5
  vec2 pixel = vec2(window.x - 0.5, float(image_size.y) - window.y - 0.5);
  vec3 d = voxel_pixel_ray(pixel, image_size, world_to_camera, tan_half_fov, shift_ndc);
  if (voxel_ray_octant(d) != octant) discard;
  float alpha = voxel_alpha(boxes[v_voxel], densities[2u * v_voxel], densities[2u * v_voxel + 1u], camera_position,
                            d, samples_per_voxel);
  if (alpha < kVoxelMinAlpha) discard;
  out_color = vec4(v_color * alpha, alpha);
}
