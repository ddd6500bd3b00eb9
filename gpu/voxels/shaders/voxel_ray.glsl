// SVRaster's per-pixel rule for one voxel (voxel/voxel_rasterizer.cpp pixel_ray, voxel_tau,
// alpha_of_tau), shared by the raster pipeline's fragment stage (voxel_raster.frag.glsl) and the
// compute tile rasterizer (voxel_tile_march.comp.glsl), so both run the same arithmetic: the
// pixel's ray (centre at integer coordinates, row 0 = top), its sign octant, a slab test against
// the box, K midpoint samples of the trilinear raw density through exp_linear_11,
// tau = sum 100 dt sigma, alpha = min(0.99999, 1 - exp(-tau)); 0 where the ray misses the box.
// docs/gpu.md "Voxels on the GPU".
const float kVoxelStepScale = 100.0;
const float kVoxelMaxAlpha = 0.99999;
const float kVoxelMinAlpha = 1e-5;
const float kVoxelMinTransmittance = 1e-4;

// scene/voxel_scene.cpp exp_linear_11.
float exp_linear_11(float x) { return x > 1.1 ? x : exp(x / 1.1 - 1.0 + log(1.1)); }

float voxel_trilinear(vec4 c0123, vec4 c4567, vec3 t) {
  // Corner i at (x, y, z) = bits (2, 1, 0): along z first, then y, then x.
  vec4 z0 = vec4(c0123.x, c0123.z, c4567.x, c4567.z), z1 = vec4(c0123.y, c0123.w, c4567.y, c4567.w);
  vec4 along_z = mix(z0, z1, t.z);                  // (x0y0, x0y1, x1y0, x1y1)
  vec2 along_y = mix(along_z.xz, along_z.yw, t.y);  // (x0, x1)
  return mix(along_y.x, along_y.y, t.x);
}

// The world direction of pixel (x, y) (row 0 = top) of an image_size image seen through a camera
// with world_to_camera, tan_half_fov and shift_ndc (render::Camera).
vec3 voxel_pixel_ray(vec2 pixel, ivec2 image_size, mat3 world_to_camera, vec2 tan_half_fov, vec2 shift_ndc) {
  vec2 ndc = (2.0 * pixel + 1.0) / vec2(image_size) - 1.0;
  vec3 d_cam = vec3((ndc - shift_ndc) * tan_half_fov, 1.0);
  return normalize(transpose(world_to_camera) * d_cam);
}

// Bit 2 = x, 1 = y, 0 = z negative (voxel/ray_order.hpp direction_octant).
int voxel_ray_octant(vec3 d) { return (d.x < 0.0 ? 4 : 0) | (d.y < 0.0 ? 2 : 0) | (d.z < 0.0 ? 1 : 0); }

// The voxel's alpha on the ray origin + t d (box: min corner, edge; densities of corners 0-3, 4-7).
float voxel_alpha(vec4 box, vec4 c0123, vec4 c4567, vec3 origin, vec3 d, int samples_per_voxel) {
  vec3 inv = 1.0 / d;
  vec3 ta = (box.xyz - origin) * inv, tb = (box.xyz + box.w - origin) * inv;
  vec3 tmin = min(ta, tb), tmax = max(ta, tb);
  float t_in = max(max(tmin.x, tmin.y), max(tmin.z, 0.0));
  float t_out = min(min(tmax.x, tmax.y), tmax.z);
  if (!(t_out > t_in)) return 0.0;
  float dt = (t_out - t_in) / float(samples_per_voxel);
  float tau = 0.0;
  for (int s = 0; s < samples_per_voxel; ++s) {
    vec3 p = origin + (t_in + (float(s) + 0.5) * dt) * d;
    vec3 local = clamp((p - box.xyz) / box.w, 0.0, 1.0);
    tau += kVoxelStepScale * dt * exp_linear_11(voxel_trilinear(c0123, c4567, local));
  }
  return min(kVoxelMaxAlpha, 1.0 - exp(-tau));
}
