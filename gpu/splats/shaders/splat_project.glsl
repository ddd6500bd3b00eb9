// The projection of one Gaussian for one camera: the GLSL twin of render/preprocess.cpp
// (forward.cu preprocessCUDA; docs/rendering.md "The CPU reference rasterizer"). Written operation
// for operation as the CPU code so the two agree to rounding; `precise` keeps the compiler from
// fusing multiply-adds where an integer (radius, tile rectangle) is derived from the result.
// #included by the per-view preprocess (one camera in uniforms) and the compute tile
// rasterizer's (a camera per view from a buffer): the includer declares the camera's values,
// as uniforms or globals, before this file:
//   mat3 world_to_camera; vec3 camera_position; vec2 tan_half_fov, focal_px, shift_ndc;
//   ivec2 image_size, tile_grid; float dilation_px2, scale_modifier; vec3 sh_origin;
// and the scene's positions, scales and rotations buffers.
#include "gpu/splats/shaders/splat_record.glsl"
#include "gpu/splats/shaders/sh_color.glsl"

const int kTileSize = 16;

// Section 3.2: Sigma = R S S^T R^T of the unit quaternion (w, x, y, z); R in GLSL column order.
mat3 covariance_3d(vec3 scale, vec4 q) {
  float r = q.x, x = q.y, y = q.z, z = q.w;
  mat3 R;
  R[0] = vec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + r * z), 2.0 * (x * z - r * y));
  R[1] = vec3(2.0 * (x * y - r * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + r * x));
  R[2] = vec3(2.0 * (x * z + r * y), 2.0 * (y * z - r * x), 1.0 - 2.0 * (x * x + y * y));
  mat3 S = mat3(0.0);
  S[0][0] = scale_modifier * scale.x;
  S[1][1] = scale_modifier * scale.y;
  S[2][2] = scale_modifier * scale.z;
  mat3 M = R * S;
  return M * transpose(M);
}

// Section 3.3 with the principal-point shift (the clamp window follows the shifted frustum,
// 0.3 tan beyond each side; the reference's 1.3 tan when the shift is 0).
vec3 covariance_2d(vec3 t, mat3 cov3d) {
  float lim_x_pos = (1.0 - shift_ndc.x) * tan_half_fov.x + 0.3 * tan_half_fov.x;
  float lim_x_neg = (1.0 + shift_ndc.x) * tan_half_fov.x + 0.3 * tan_half_fov.x;
  float lim_y_pos = (1.0 - shift_ndc.y) * tan_half_fov.y + 0.3 * tan_half_fov.y;
  float lim_y_neg = (1.0 + shift_ndc.y) * tan_half_fov.y + 0.3 * tan_half_fov.y;
  float txtz = t.x / t.z, tytz = t.y / t.z;
  t.x = min(lim_x_pos, max(-lim_x_neg, txtz)) * t.z;
  t.y = min(lim_y_pos, max(-lim_y_neg, tytz)) * t.z;
  mat3 J = mat3(0.0);  // J[col][row]
  J[0][0] = focal_px.x / t.z;
  J[2][0] = -(focal_px.x * t.x) / (t.z * t.z);
  J[1][1] = focal_px.y / t.z;
  J[2][1] = -(focal_px.y * t.y) / (t.z * t.z);
  mat3 T = J * world_to_camera;
  mat3 cov = T * cov3d * transpose(T);
  return vec3(cov[0][0] + dilation_px2, cov[1][0], cov[1][1] + dilation_px2);
}


// Gaussian i projected for the camera: its record and its depth key (a positive depth's float bits,
// which order as the floats); false when culled.
bool project_splat(uint i, out SplatRecord record, out uint key) {
  vec4 position_opacity = positions[i];
  vec3 mean = position_opacity.xyz;
  precise vec3 t = world_to_camera * (mean - camera_position);
  if (t.z <= 0.2) {  // in_frustum: near cull only (auxiliary.h)
    return false;
  }
  mat3 cov3d = covariance_3d(scales[i].xyz, rotations[i]);
  precise vec3 cov = covariance_2d(t, cov3d);
  precise float det = cov.x * cov.z - cov.y * cov.y;
  if (det == 0.0) {
    return false;
  }
  float det_inv = 1.0 / det;
  vec3 conic = vec3(cov.z * det_inv, -cov.y * det_inv, cov.x * det_inv);

  precise float mid = 0.5 * (cov.x + cov.z);
  precise float lambda1 = mid + sqrt(max(0.1, mid * mid - det));
  precise float lambda2 = mid - sqrt(max(0.1, mid * mid - det));
  precise float radius = ceil(3.0 * sqrt(max(lambda1, lambda2)));
  // Camera::project_ndc: the reference's full_proj_transform, / (w + 1e-7), then ndc2Pix.
  precise float inv_w = 1.0 / (t.z + 1e-7);
  precise vec2 ndc = vec2((t.x / tan_half_fov.x + shift_ndc.x * t.z) * inv_w,
                          (t.y / tan_half_fov.y + shift_ndc.y * t.z) * inv_w);
  precise vec2 px = vec2(((ndc.x + 1.0) * float(image_size.x) - 1.0) * 0.5,
                         ((ndc.y + 1.0) * float(image_size.y) - 1.0) * 0.5);
  // getRect (auxiliary.h): int() truncates toward zero, as in CUDA and C++.
  ivec2 rmin = ivec2(min(tile_grid.x, max(0, int((px.x - radius) / float(kTileSize)))),
                     min(tile_grid.y, max(0, int((px.y - radius) / float(kTileSize)))));
  ivec2 rmax = ivec2(min(tile_grid.x, max(0, int((px.x + radius + float(kTileSize - 1)) / float(kTileSize)))),
                     min(tile_grid.y, max(0, int((px.y + radius + float(kTileSize - 1)) / float(kTileSize)))));
  if ((rmax.x - rmin.x) * (rmax.y - rmin.y) == 0) {
    return false;
  }
  vec3 color = sh_color(i, normalize(mean - sh_origin));
  record = SplatRecord(vec4(px, t.z, position_opacity.w), vec4(conic, radius), vec4(color, 0.0), ivec4(rmin, rmax));
  key = floatBitsToUint(t.z);
  return true;
}
