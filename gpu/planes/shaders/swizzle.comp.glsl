// G2LF swizzle blending (paper Alg. 1 lines 6-12), the twin of render/swizzle_blend.cpp: one
// invocation per pixel (x, y) of VIEWS consecutive views j (gl_GlobalInvocationID.z * VIEWS + i).
// The ray of that pixel meets plane k at the reference coordinate of Eq. (u_prime), split per
// plane as u' = dx_j parallax_k + scale_k u; C_k and T_k are sampled there (nearest, or bilinear
// by hand from four texelFetches with the CPU's weights, texels outside the plane reading as
// empty (0, 0, 0, 1)) and composited front to back with Eq. (alpha_blend). The planes are the
// outer loop: a plane's factors and sample row (they do not depend on the view) are computed
// once for the invocation's views, whose samples lie on one row of the plane, so the planes are
// read once per VIEWS views rather than once per view (docs/gpu.md "Swizzle"). Rows are the CPU's
// (row 0 = top); plane and quilt textures store them bottom-up (GL). A view's pixel stops once
// T < 0.5/255, as the CPU, and the invocation once all of its views have. Arithmetic follows the
// CPU's order of operations and is `precise` (no fused multiply-add), so sample positions, and
// with them the nearest texel, agree with the CPU's. With TABLE the per-plane factors and the
// per-view-and-plane columns come from the table swizzle_table.comp.glsl wrote this frame (the
// same expressions, so the same floats). With HW_BILINEAR (and BILINEAR) a plane is sampled by
// the texture unit (a sampler with GL_LINEAR and a (0, 0, 0, 1) border), one fetch instead of
// four, whose weights are the unit's own (8 bits of fraction on NVIDIA), not the CPU's.
// Defines: BILINEAR 0|1, HW_BILINEAR 0|1, TABLE 0|1, QUILT_FORMAT (rgba8 | rgba16f | rgba32f),
// VIEWS (views per invocation).
#include "gpu/planes/shaders/swizzle_io.h"
#include "gpu/planes/shaders/plane_table.glsl"

layout(local_size_x = kSwizzleGroupWidth, local_size_y = kSwizzleGroupHeight) in;

layout(binding = kSwizzlePlanesUnit) uniform sampler2DArray planes;
layout(QUILT_FORMAT, binding = kSwizzleQuiltImage) uniform writeonly image2D quilt;

// PlaneTable (plane_table.glsl): table.plane_count, table.splats_binned, plane[k].
#if TABLE
layout(std430, binding = kSwizzlePlaneFactorsBinding) readonly buffer PlaneFactors { vec2 plane_factors[]; };  // scale_y, beta
layout(std430, binding = kSwizzleViewPlaneColumnsBinding) readonly buffer ViewPlaneColumns { float view_plane_column[]; };  // [k V + j]
#else
layout(std430, binding = kSwizzleViewOffsetsBinding) readonly buffer ViewOffsets { float view_offset[]; };  // dx_j
#endif

uniform ivec2 view_size;   // W, H of a view
uniform ivec2 plane_size;  // Wp, Hp
uniform ivec3 tiles;       // columns, tile width, tile height of the quilt layout
uniform float focal_distance;
uniform float tan_x, tan_y;    // base camera tan(theta/2)
uniform float tan_rx, tan_ry;  // reference camera tan(theta'/2)
uniform float d_forward_eff;
uniform vec3 background;
uniform int view_count;  // V

const float kMinTransmittance = 0.5 / 255.0;

vec4 fetch(int x, int row, int layer) {
  if (x < 0 || x >= plane_size.x || row < 0 || row >= plane_size.y) return vec4(0.0, 0.0, 0.0, 1.0);
  return texelFetch(planes, ivec3(x, plane_size.y - 1 - row, layer), 0);  // rows bottom-up
}

vec4 sample_plane(float px, float py, int layer) {
#if BILINEAR && HW_BILINEAR
  // Texel centres at (i + 0.5) / size; row py of the CPU's plane is texel row Hp - 1 - py.
  const vec2 size = vec2(plane_size);
  return textureLod(planes, vec3((px + 0.5) / size.x, (size.y - 0.5 - py) / size.y, float(layer)), 0.0);
#elif BILINEAR
  const int row0 = int(floor(py)), col0 = int(floor(px));
  precise const float fy = py - float(row0), fx = px - float(col0);
  const vec4 a = fetch(col0, row0, layer), b = fetch(col0 + 1, row0, layer);
  const vec4 c = fetch(col0, row0 + 1, layer), e = fetch(col0 + 1, row0 + 1, layer);
  precise vec4 top = (1.0 - fx) * a + fx * b;
  precise vec4 bottom = (1.0 - fx) * c + fx * e;
  precise vec4 mixed = (1.0 - fy) * top + fy * bottom;
  return mixed;
#else
  return fetch(int(floor(px + 0.5)), int(floor(py + 0.5)), layer);
#endif
}

void main() {
  const int x = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
  const int j0 = int(gl_GlobalInvocationID.z) * VIEWS;
  if (x >= min(view_size.x, tiles.y) || y >= min(view_size.y, tiles.z)) return;
  const int views = min(VIEWS, view_count - j0);
  const float W = float(view_size.x), H = float(view_size.y);
  const float Wp = float(plane_size.x), Hp = float(plane_size.y);
  precise const float v_ndc = (2.0 * float(y) + 1.0) / H - 1.0;

  vec3 C[VIEWS];
  float t[VIEWS];
  for (int i = 0; i < VIEWS; ++i) {
    C[i] = vec3(0.0);
    t[i] = i < views ? 1.0 : 0.0;  // views past the last are done from the start
  }
  const uint count = table.plane_count;
  bool open = true;  // some view's pixel still lets light through
  for (uint k = 0u; k < count && open; ++k) {
#if TABLE
    const vec2 factors = plane_factors[k];
    const float scale_y = factors.x, beta = factors.y;
#else
    const float d = plane[k].depth;
    precise const float depth_ref = d - d_forward_eff;
    precise const float parallax = (focal_distance - d) / focal_distance / (depth_ref * tan_rx);
    precise const float scale_x = d * tan_x / (depth_ref * tan_rx);
    precise const float scale_y = d * tan_y / (depth_ref * tan_ry);
    precise const float step = 2.0 * scale_x / W;
    precise const float beta = step * Wp * 0.5;
#endif
    precise const float py = ((scale_y * v_ndc + 1.0) * Hp - 1.0) * 0.5;
    const int layer = int(k);
    open = false;
    for (int i = 0; i < VIEWS; ++i) {
      if (t[i] < kMinTransmittance) continue;
#if TABLE
      const float alpha = view_plane_column[k * uint(view_count) + uint(j0 + i)];
#else
      precise const float u_left = view_offset[j0 + i] * parallax - scale_x;
      precise const float alpha = ((u_left + 0.5 * step + 1.0) * Wp - 1.0) * 0.5;
#endif
      precise const float px = alpha + beta * float(x);
      const vec4 s = sample_plane(px, py, layer);
      C[i] += t[i] * s.rgb;
      t[i] *= s.a;
      open = open || t[i] >= kMinTransmittance;
    }
  }
  // Quilt texture rows bottom-up (GL): view j's tile starts at row (j / columns) * tile height,
  // and the view's top row y = 0 is the tile's highest.
  for (int i = 0; i < views; ++i) {
    const int j = j0 + i;
    const int tile_x = (j % tiles.x) * tiles.y;
    const int row = (j / tiles.x) * tiles.z + (tiles.z - 1 - y);
    imageStore(quilt, ivec2(tile_x + x, row), vec4(C[i] + t[i] * background, 1.0));
  }
}
