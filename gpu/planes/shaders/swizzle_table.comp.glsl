// The swizzle's sample positions per view and plane, once a frame on the GPU (docs/gpu.md
// "Swizzle"): Eq. (u_prime) split per plane as u' = dx_j parallax_k + scale_k u, evaluated here
// for every plane k of the frame (its depth d_k from the plane table, which never leaves the
// GPU) and every view j, instead of per quilt pixel and plane in the swizzle. One invocation per
// (view, plane); planes past the frame's plane count are skipped. The expressions and their
// order are the swizzle's own (`precise`: no fused multiply-add), so the swizzle samples the
// same positions bit for bit with or without the table.
#include "gpu/planes/shaders/swizzle_io.h"
#include "gpu/planes/shaders/plane_table.glsl"

layout(local_size_x = kSwizzleTableGroupSize) in;

// PlaneTable (plane_table.glsl): table.plane_count, table.splats_binned, plane[k].
layout(std430, binding = kSwizzleViewOffsetsBinding) readonly buffer ViewOffsets { float view_offset[]; };  // dx_j
// Per plane: scale_y (for the sample row) and beta (the column step per pixel x).
layout(std430, binding = kSwizzlePlaneFactorsBinding) writeonly buffer PlaneFactors { vec2 plane_factors[]; };
// Per plane k and view j, at k * view_count + j: alpha, the column sampled by pixel x = 0.
layout(std430, binding = kSwizzleViewPlaneColumnsBinding) writeonly buffer ViewPlaneColumns { float view_plane_column[]; };

uniform ivec2 view_size;   // W, H of a view
uniform ivec2 plane_size;  // Wp, Hp
uniform float focal_distance;
uniform float tan_x, tan_y;    // base camera tan(theta/2)
uniform float tan_rx, tan_ry;  // reference camera tan(theta'/2)
uniform float d_forward_eff;
uniform int view_count;  // V

void main() {
  const int j = int(gl_GlobalInvocationID.x);
  const uint k = gl_GlobalInvocationID.y;
  if (j >= view_count || k >= table.plane_count) return;
  const float W = float(view_size.x);
  const float Wp = float(plane_size.x);
  const float d = plane[k].depth;
  precise const float depth_ref = d - d_forward_eff;
  precise const float parallax = (focal_distance - d) / focal_distance / (depth_ref * tan_rx);
  precise const float scale_x = d * tan_x / (depth_ref * tan_rx);
  precise const float scale_y = d * tan_y / (depth_ref * tan_ry);
  precise const float step = 2.0 * scale_x / W;
  precise const float beta = step * Wp * 0.5;
  if (j == 0) plane_factors[k] = vec2(scale_y, beta);
  precise const float u_left = view_offset[j] * parallax - scale_x;
  precise const float alpha = ((u_left + 0.5 * step + 1.0) * Wp - 1.0) * 0.5;
  view_plane_column[k * uint(view_count) + uint(j)] = alpha;
}
