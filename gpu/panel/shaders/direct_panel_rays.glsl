// The direct panel pass's per-ray work (docs/rendering.md "Direct panel rendering"), the GLSL twin of
// interlace::render_direct_panel (interlace/direct_panel.cpp) and render::PlaneRays
// (render/plane_rays.cpp): one fragment per panel pixel. Each channel's view fraction comes from
// lens_view.glsl (#included: the one GLSL definition the interlacer uses too); it stands for the
// camera at view position s = f - 1/2, offset dx = view_offset_at(s) (render/quilt_geometry.hpp),
// and the sweeping planes are composited front to back along that camera's ray through the
// pixel's point in the view (the interlacer's aspect fit), for that channel alone. Plane
// coordinates are Eq. (u_prime) as plane_coordinate_x_at / plane_coordinate_y write it, sampled
// as the CPU's (nearest, or bilinear from four texelFetches, empty (0, 0, 0, 1) outside); a ray
// stops below 0.5/255 transmittance. No quilt. With HW_BILINEAR (and BILINEAR) the texture unit
// filters (a sampler with GL_LINEAR and a (0, 0, 0, 1) border, as the swizzle's): one fetch
// instead of four, with the unit's own weights (8 bits of fraction on NVIDIA), not the CPU's.
// Shared by its two stages (one definition): the fragment pass (direct_panel.frag.glsl, a window's
// framebuffer) and the compute pass over panel tiles (direct_panel.comp.glsl, the offscreen
// paths). A pixel's three rays are a DirectRays; a stage begins them, composites them plane by
// plane with the plane's factors (direct_plane_factors) and ends them.
// Defines: BILINEAR 0|1, HW_BILINEAR 0|1.
#include "gpu/panel/shaders/lens_view_io.h"
#include "gpu/planes/shaders/plane_table.glsl"
#include "gpu/panel/shaders/lens_view.glsl"

layout(binding = kDirectPanelPlanesUnit) uniform sampler2DArray planes;  // rows bottom-up (gpu/planes/gl_planes.hpp)

uniform ivec2 plane_size;        // Wp, Hp
uniform float focal_distance;    // D_focal
uniform float tan_x, tan_y;      // base camera tan(theta/2)
uniform float tan_rx, tan_ry;    // reference camera tan(theta'/2)
uniform float d_forward_eff;
uniform float two_focal_distance, tan_half_cone;  // view_offset_at(s) = 2 D_focal s tan(phi/2)
uniform vec2 aspect_scale;       // interlace::aspect_fit for the views' aspect
uniform bool invert_views;       // InterlaceOptions::invert_views
uniform float fringe;            // calibration().fringe
uniform vec3 background;

const float kMinTransmittance = 0.5 / 255.0;

vec4 fetch(int x, int row, int layer) {
  if (x < 0 || x >= plane_size.x || row < 0 || row >= plane_size.y) return vec4(0.0, 0.0, 0.0, 1.0);
  return texelFetch(planes, ivec3(x, plane_size.y - 1 - row, layer), 0);
}

// The three rays of a panel pixel (one per channel): the view offsets, the pixel's point in the
// view, and what they have composited so far.
struct DirectRays {
  vec3 dx;             // view_offset_at(f - 1/2) per channel
  float u_ndc, v_ndc;  // the point in the view (v top-down, as the planes' rows)
  vec3 C, t;           // colour and transmittance per channel
};

// A pixel outside the views' aspect fit shows black: its rays start closed, with no background.
DirectRays direct_rays_begin(ivec2 pixel) {
  DirectRays r;
  r.C = vec3(0.0);
  r.t = vec3(1.0);
  r.dx = vec3(0.0);
  const vec2 tile_uv = (lens_pixel_uv(pixel) - 0.5) * aspect_scale + 0.5;
  if (any(lessThan(tile_uv, vec2(0.0))) || any(greaterThan(tile_uv, vec2(1.0)))) {
    r.t = vec3(0.0);
    r.u_ndc = r.v_ndc = 0.0;
    return r;
  }
  precise const float u_ndc = 2.0 * tile_uv.x - 1.0;
  precise const float v_ndc = 1.0 - 2.0 * tile_uv.y;
  r.u_ndc = u_ndc;
  r.v_ndc = v_ndc;
  for (int c = 0; c < 3; ++c) {
    float f = lens_view_fraction(pixel, c);
    if (invert_views) f = 1.0 - f;
    precise const float s = f - 0.5;
    r.dx[c] = two_focal_distance * s * tan_half_cone;
  }
  return r;
}

bool direct_rays_open(DirectRays r) { return max(r.t.r, max(r.t.g, r.t.b)) >= kMinTransmittance; }

// Plane k's factors of Eq. (u_prime) from its depth: (parallax, scale_x, scale_y), the CPU's
// expressions in its order (render/plane_rays.cpp), `precise` so every stage gets the same floats.
vec3 direct_plane_factors(uint k) {
  const float d = plane[k].depth;
  precise const float depth_ref = d - d_forward_eff;
  precise const float parallax = (focal_distance - d) / focal_distance / (depth_ref * tan_rx);
  precise const float scale_x = d * tan_x / (depth_ref * tan_rx);
  precise const float scale_y = d * tan_y / (depth_ref * tan_ry);
  return vec3(parallax, scale_x, scale_y);
}

// Composites plane `layer` (its factors from direct_plane_factors) into the rays still open.
void direct_rays_composite(inout DirectRays r, vec3 factors, int layer) {
  const float parallax = factors.x, scale_x = factors.y, scale_y = factors.z;
  const float Wp = float(plane_size.x), Hp = float(plane_size.y);
  precise const float py = ((scale_y * r.v_ndc + 1.0) * Hp - 1.0) * 0.5;
  for (int c = 0; c < 3; ++c) {
    if (r.t[c] < kMinTransmittance) continue;
    precise const float px = ((r.dx[c] * parallax + r.u_ndc * scale_x + 1.0) * Wp - 1.0) * 0.5;
    vec4 sample_k;
#if BILINEAR && HW_BILINEAR
    // Texel centres at (i + 0.5) / size; row py of the CPU's plane is texel row Hp - 1 - py.
    sample_k = textureLod(planes, vec3((px + 0.5) / Wp, (Hp - 0.5 - py) / Hp, float(layer)), 0.0);
#elif BILINEAR
    const int row0 = int(floor(py)), col0 = int(floor(px));
    precise const float fy = py - float(row0), fx = px - float(col0);
    const vec4 a = fetch(col0, row0, layer), b = fetch(col0 + 1, row0, layer);
    const vec4 e = fetch(col0, row0 + 1, layer), g = fetch(col0 + 1, row0 + 1, layer);
    precise vec4 mixed = (1.0 - fy) * ((1.0 - fx) * a + fx * b) + fy * ((1.0 - fx) * e + fx * g);
    sample_k = mixed;
#else
    sample_k = fetch(int(floor(px + 0.5)), int(floor(py + 0.5)), layer);
#endif
    r.C[c] += r.t[c] * sample_k[c];
    r.t[c] *= sample_k.a;
  }
}

// The pixel's RGB: the background behind what lets light through, then
// interlace::fringe_gain: every other row darkened (docs/display-model.md "Vendor interlacing
// rules"). Black outside the aspect fit.
vec3 direct_rays_end(DirectRays r, ivec2 pixel) {
  const vec2 tile_uv = (lens_pixel_uv(pixel) - 0.5) * aspect_scale + 0.5;
  if (any(lessThan(tile_uv, vec2(0.0))) || any(greaterThan(tile_uv, vec2(1.0)))) return vec3(0.0);
  const float fringe_gain = 1.0 - abs(fringe) * floor(mod(float(pixel.y) + 0.5 + ceil(fringe / 2.0), 2.0));
  return (r.C + r.t * background) * fringe_gain;
}
