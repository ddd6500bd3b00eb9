// G2LF swizzle blending (paper Alg. 1 lines 6-12), the twin of render/swizzle_blend.cpp: one
// invocation per pixel (x, y) of view j. The ray of that pixel meets plane k at the reference
// coordinate of Eq. (u_prime), split per plane as u' = dx_j parallax_k + scale_k u; C_k and T_k
// are sampled there (nearest, or bilinear by hand from four texelFetches with the CPU's weights,
// texels outside the plane reading as empty (0, 0, 0, 1)) and composited front to back with
// Eq. (alpha_blend). Rows are the CPU's (row 0 = top); plane and quilt textures store them
// bottom-up (GL). The pixel stops once T < 0.5/255, as the CPU. Arithmetic follows the CPU's
// order of operations and is `precise` (no fused multiply-add), so sample positions, and with
// them the nearest texel, agree with the CPU's.
// Defines: BILINEAR 0|1, QUILT_FORMAT (rgba8 | rgba16f | rgba32f).
layout(local_size_x = 16, local_size_y = 8, local_size_z = 1) in;

layout(binding = 0) uniform sampler2DArray planes;
layout(QUILT_FORMAT, binding = 0) uniform writeonly image2D quilt;

// The plane table (gpu/gl_planes.hpp): header, then d_k and the first splat per plane.
struct PlaneEntry {
  float depth;
  uint begin;
};
layout(std430, binding = 0) readonly buffer PlaneTable {
  uint plane_count;
  uint splats_binned;
  uint pad0, pad1;
  PlaneEntry plane[];
};
layout(std430, binding = 1) readonly buffer ViewOffsets { float view_offset[]; };  // dx_j

uniform ivec2 view_size;   // W, H of a view
uniform ivec2 plane_size;  // Wp, Hp
uniform ivec3 tiles;       // columns, tile width, tile height of the quilt layout
uniform float focal_distance;
uniform float tan_x, tan_y;    // base camera tan(theta/2)
uniform float tan_rx, tan_ry;  // reference camera tan(theta'/2)
uniform float d_forward_eff;
uniform vec3 background;

const float kMinTransmittance = 0.5 / 255.0;

vec4 fetch(int x, int row, int layer) {
  if (x < 0 || x >= plane_size.x || row < 0 || row >= plane_size.y) return vec4(0.0, 0.0, 0.0, 1.0);
  return texelFetch(planes, ivec3(x, plane_size.y - 1 - row, layer), 0);  // rows bottom-up
}

void main() {
  const int x = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
  const int j = int(gl_GlobalInvocationID.z);
  if (x >= min(view_size.x, tiles.y) || y >= min(view_size.y, tiles.z)) return;
  const float W = float(view_size.x), H = float(view_size.y);
  const float Wp = float(plane_size.x), Hp = float(plane_size.y);
  precise const float v_ndc = (2.0 * float(y) + 1.0) / H - 1.0;
  const float dx = view_offset[j];

  vec3 C = vec3(0.0);
  float t = 1.0;
  const uint count = plane_count;
  for (uint k = 0u; k < count && t >= kMinTransmittance; ++k) {
    const float d = plane[k].depth;
    precise const float depth_ref = d - d_forward_eff;
    precise const float parallax = (focal_distance - d) / focal_distance / (depth_ref * tan_rx);
    precise const float scale_x = d * tan_x / (depth_ref * tan_rx);
    precise const float scale_y = d * tan_y / (depth_ref * tan_ry);
    precise const float py = ((scale_y * v_ndc + 1.0) * Hp - 1.0) * 0.5;
    precise const float step = 2.0 * scale_x / W;
    precise const float beta = step * Wp * 0.5;
    precise const float u_left = dx * parallax - scale_x;
    precise const float alpha = ((u_left + 0.5 * step + 1.0) * Wp - 1.0) * 0.5;
    precise const float px = alpha + beta * float(x);
    const int layer = int(k);
    vec4 s;
#if BILINEAR
    const int row0 = int(floor(py)), col0 = int(floor(px));
    precise const float fy = py - float(row0), fx = px - float(col0);
    const vec4 a = fetch(col0, row0, layer), b = fetch(col0 + 1, row0, layer);
    const vec4 c = fetch(col0, row0 + 1, layer), e = fetch(col0 + 1, row0 + 1, layer);
    precise vec4 top = (1.0 - fx) * a + fx * b;
    precise vec4 bottom = (1.0 - fx) * c + fx * e;
    precise vec4 mixed = (1.0 - fy) * top + fy * bottom;
    s = mixed;
#else
    s = fetch(int(floor(px + 0.5)), int(floor(py + 0.5)), layer);
#endif
    C += t * s.rgb;
    t *= s.a;
  }
  // Quilt texture rows bottom-up (GL): view j's tile starts at row (j / columns) * tile height,
  // and the view's top row y = 0 is the tile's highest.
  const int tile_x = (j % tiles.x) * tiles.y;
  const int row = (j / tiles.x) * tiles.z + (tiles.z - 1 - y);
  imageStore(quilt, ivec2(tile_x + x, row), vec4(C + t * background, 1.0));
}
