// The view a panel subpixel shows: the GLSL twin of display::LensModel's phase and view fraction
// (display/lens_model.cpp), in single precision, shared by the interlacing shader
// (interlace.frag.glsl) and the direct panel pass (direct_panel.frag.glsl): one definition.
// Constants come from gpu::GlLensView (gpu/panel/gl_lens_view.cpp), which takes them from LensModel.
//
// Precision (docs/gpu.md "Single precision"): the phase A(u, v) = (u + v tilt) pitch' - center
// + w(u, v) reaches hundreds of lens periods, where a float keeps only ~1e-5 of a period. Its
// large part is split off on the CPU in double: A = column[x] + row[j] + subpixel + w, with
// column[x] = frac((x + 1/2) / W pitch') and row[j] = frac((j + 1/2) / H tilt pitch' - center)
// reduced to [0, 1) in double and stored as floats (error <= 2^-25 each), the subpixel term
// (du + dv tilt) pitch' (|.| < 1) from LensModel's own offsets, and w from the correction
// grid. Every float here is < 4 in magnitude, so the sum and frac() lose at most ~5e-7 period:
// a subpixel shows the CPU's view unless its double fraction lies within kLensViewTolerance of
// a view boundary (tests/gpu/gl_lens_view_test.cpp measures it over whole 8K panels).
#include "gpu/panel/shaders/lens_view_io.h"

layout(binding = kLensCorrectionUnit) uniform sampler2D correction;  // w(u, v) on a grid over [0, 1]^2, R32F
// column[x] for x < screenW, then row[j] (j bottom-up) for j < screenH: frac() of the phase parts.
layout(std430, binding = kLensPhasePartsBinding) readonly buffer LensPhaseParts { float phase_part[]; };

uniform ivec2 panel_size;  // screenW, screenH
uniform bool inv_view;     // calibration().inv_view
// For the 8 pixel classes (x mod 2) + 2 (j mod 4), j bottom-up, and each channel:
// LensModel::subpixel_uv - pixel_uv (every cell pattern and flipSubp repeat with that period, so
// the table is LensModel's own offsets), and its phase (du + dv tilt) pitch'.
uniform vec2 subpixel_offset[kLensSubpixelEntries];
uniform float subpixel_phase[kLensSubpixelEntries];
uniform bool has_correction;
uniform ivec2 correction_grid;  // grid points per axis; point i at u = i / (grid.x - 1)

// LensModel::pixel_uv of pixel (x, j), j bottom-up: ((x + 0.5) / W, (j + 0.5) / H).
vec2 lens_pixel_uv(ivec2 pixel) { return (vec2(pixel) + 0.5) / vec2(panel_size); }

// CorrectionField::operator()(u, v), bilinear on the grid (texel centres on the grid points).
float correction_at(vec2 p) {
  if (!has_correction) return 0.0;
  const vec2 g = clamp(p, 0.0, 1.0) * vec2(correction_grid - 1);
  const ivec2 i0 = min(ivec2(g), correction_grid - 2);
  const vec2 a = g - vec2(i0);
  const float w00 = texelFetch(correction, i0, 0).r;
  const float w10 = texelFetch(correction, i0 + ivec2(1, 0), 0).r;
  const float w01 = texelFetch(correction, i0 + ivec2(0, 1), 0).r;
  const float w11 = texelFetch(correction, i0 + ivec2(1, 1), 0).r;
  return mix(mix(w00, w10, a.x), mix(w01, w11, a.x), a.y);
}

// LensModel::subpixel_view_fraction(x, row, c): frac(A), 1 - frac(A) under invView, the vendor
// clamp to [1e-5, 0.999999].
float lens_view_fraction(ivec2 pixel, int c) {
  const int k = ((pixel.x & 1) + 2 * (pixel.y & 3)) * 3 + c;
  const float w = correction_at(lens_pixel_uv(pixel) + subpixel_offset[k]);
  precise const float a = phase_part[pixel.x] + phase_part[panel_size.x + pixel.y] + subpixel_phase[k] + w;
  const float frac_a = a - floor(a);
  const float f = inv_view ? 1.0 - frac_a : frac_a;
  return clamp(f, 1e-5, 0.999999);
}
