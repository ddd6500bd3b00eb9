// The interlacer's per-pixel work, shared by its two stages: the fragment pass (interlace.frag.glsl,
// a window's framebuffer) and the compute pass (interlace.comp.glsl, the offscreen paths). The
// GLSL twin of interlace::Interlacer (interlace/interlacer.cpp), in single precision. Each
// subpixel's view fraction comes from lens_view.glsl (#included: the one GLSL definition of
// display::LensModel's phase and view fraction, which says where single precision is enough);
// the lines marked "Interlacer::" repeat that function's arithmetic in the same order. Every
// constant comes from the CPU (gpu/panel/gl_interlacer.cpp, gpu/panel/gl_lens_view.cpp).
#include "gpu/panel/shaders/lens_view_io.h"
#include "gpu/panel/shaders/lens_view.glsl"

layout(binding = kInterlaceQuiltUnit) uniform sampler2D quilt;  // rows bottom-up, view 0 in the bottom-left tile

uniform int views;
uniform int quilt_cols;
uniform ivec2 tile_size;     // QuiltLayout::tile_width(), tile_height()
uniform vec2 aspect_scale;   // (nu, nv) scale of the aspect fit: one of them is 1
uniform bool invert_views;   // InterlaceOptions::invert_views
uniform bool linear_blend;   // InterlaceOptions::blend == kLinear
uniform float fringe;        // calibration().fringe

// Interlacer::sample_tile: bilinear inside tile `view`, clamped to its texels so no
// neighbouring view bleeds in; fixed-function filtering would round the weights (8 bits on
// many GPUs) and could not clamp per tile.
vec3 sample_tile(int view, ivec2 t0, ivec2 t1, vec2 weight) {
  const ivec2 origin = ivec2(view % quilt_cols, view / quilt_cols) * tile_size;
  const vec3 c00 = texelFetch(quilt, origin + ivec2(t0.x, t0.y), 0).rgb;
  const vec3 c10 = texelFetch(quilt, origin + ivec2(t1.x, t0.y), 0).rgb;
  const vec3 c01 = texelFetch(quilt, origin + ivec2(t0.x, t1.y), 0).rgb;
  const vec3 c11 = texelFetch(quilt, origin + ivec2(t1.x, t1.y), 0).rgb;
  const vec3 bottom = c00 * (1.0 - weight.x) + c10 * weight.x;
  const vec3 top = c01 * (1.0 - weight.x) + c11 * weight.x;
  return bottom * (1.0 - weight.y) + top * weight.y;
}

// The panel's RGB at pixel (x, j), j bottom-up (Interlacer::interlace's per-pixel work).
vec3 interlace_pixel(ivec2 pixel) {
  // Interlacer::sample_for, aspect fit: only the tile lookup is scaled (docs/display-model.md
  // "Vendor interlacing rules").
  const vec2 tile_uv = (lens_pixel_uv(pixel) - 0.5) * aspect_scale + 0.5;
  if (any(lessThan(tile_uv, vec2(0.0))) || any(greaterThan(tile_uv, vec2(1.0)))) return vec3(0.0);
  // Interlacer::sample_tile's texel coordinates, the same for every channel and view.
  const vec2 texel = clamp(tile_uv * vec2(tile_size) - 0.5, vec2(0.0), vec2(tile_size - 1));
  const ivec2 t0 = ivec2(texel);
  const ivec2 t1 = min(t0 + 1, tile_size - 1);
  const vec2 weight = texel - vec2(t0);

  vec3 rgb;
  for (int c = 0; c < 3; ++c) {
    float f = lens_view_fraction(pixel, c);
    if (invert_views) f = 1.0 - f;
    vec3 value;
    if (!linear_blend) {
      // LensModel::view_index: floor(f V) clamped to [0, V - 1].
      const int view = clamp(int(floor(f * float(views))), 0, views - 1);
      value = sample_tile(view, t0, t1, weight);
    } else {
      // Interlacer::sample_for, linear: the two view centres (k + 0.5) / V around f, clamped
      // at the cone edges rather than wrapped.
      const float t = clamp(f * float(views) - 0.5, 0.0, float(views - 1));
      const int view_a = min(int(floor(t)), views - 1);
      const int view_b = min(view_a + 1, views - 1);
      const float weight_b = t - float(view_a);
      value = sample_tile(view_a, t0, t1, weight);
      if (weight_b > 0.0) {
        const vec3 b = sample_tile(view_b, t0, t1, weight);
        value += (b - value) * weight_b;
      }
    }
    rgb[c] = value[c];
  }
  // Interlacer::interlace, fringe correction: every other row darkened (docs/display-model.md
  // "Vendor interlacing rules").
  const float fringe_gain =
      1.0 - abs(fringe) * floor(mod(float(pixel.y) + 0.5 + ceil(fringe / 2.0), 2.0));
  return rgb * fringe_gain;
}
