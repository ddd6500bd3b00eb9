// The interlacing shader: the GLSL twin of interlace::Interlacer (interlace/interlacer.cpp) and
// of calib::LensModel (display/lens_model.cpp), one fragment per panel pixel. Every
// constant comes from LensModel (gpu/gl_interlacer.cpp sets them); the lines marked "LensModel::"
// or "Interlacer::" repeat that function's arithmetic in the same order. The phase reaches several
// hundred lens periods, so it is computed in double precision like the CPU reference: float32
// keeps only about 1e-5 period of frac(A) (looking-glass.md 3.4), and subpixels that close to a
// view boundary show the neighbouring view (measured: 0.003-0.01 % of them on the test panels,
// which are 1/4-1/8 of full size; in double none do).

layout(binding = 0) uniform sampler2D quilt;       // rows bottom-up, view 0 in the bottom-left tile
layout(binding = 1) uniform sampler2D correction;  // w(u, v) on a grid over [0, 1]^2, R32F

uniform ivec2 panel_size;       // screenW, screenH
uniform dvec2 inv_panel_size;   // 1 / screenW, 1 / screenH (multiplying is exact in IEEE double;
                                // GLSL does not promise a correctly rounded double division)
uniform double pitch_periods;   // LensModel::pitch_periods()
uniform double tilt;            // LensModel::tilt()
uniform double center_periods;  // calibration().center_periods
uniform bool inv_view;          // calibration().inv_view
// LensModel::subpixel_uv(x, row, c) - pixel_uv(x, row) for the 8 pixel classes
// (x mod 2) + 2 (j mod 4), j bottom-up: every cell pattern (and the classic 1/3 stride with
// flipSubp) repeats with that period, so the table is LensModel's own offsets, not a re-derivation.
uniform dvec2 subpixel_offset[8 * 3];
uniform bool has_correction;
uniform ivec2 correction_grid;  // grid points per axis; point i at u = i / (grid.x - 1)

uniform int views;
uniform int quilt_cols;
uniform ivec2 tile_size;        // QuiltLayout::tile_width(), tile_height()
uniform dvec2 aspect_scale;     // (nu, nv) scale of the aspect fit: one of them is 1
uniform bool invert_views;      // InterlaceOptions::invert_views
uniform bool linear_blend;      // InterlaceOptions::blend == kLinear
uniform float fringe;           // calibration().fringe

layout(location = 0) out vec4 panel;

// CorrectionField::operator()(u, v), bilinear on the grid (texel centres on the grid points).
// bspline_weights clamps t to [0, 1]; clamping the grid coordinate does the same.
double correction_at(dvec2 p) {
  if (!has_correction) return 0.0;
  // The grid coordinate in double: a float u would move it by up to 1e-4 texel on a 2000-point grid.
  const dvec2 g = clamp(p, 0.0LF, 1.0LF) * dvec2(correction_grid - 1);
  const ivec2 i0 = min(ivec2(g), correction_grid - 2);
  const vec2 a = vec2(g - dvec2(i0));
  const float w00 = texelFetch(correction, i0, 0).r;
  const float w10 = texelFetch(correction, i0 + ivec2(1, 0), 0).r;
  const float w01 = texelFetch(correction, i0 + ivec2(0, 1), 0).r;
  const float w11 = texelFetch(correction, i0 + ivec2(1, 1), 0).r;
  return double(mix(mix(w00, w10, a.x), mix(w01, w11, a.x), a.y));
}

// LensModel::phase: A(u, v) = (u + v tilt) pitch' - center + w(u, v).
double lens_phase(dvec2 p) {
  return (p.x + p.y * tilt) * pitch_periods - center_periods + correction_at(p);
}

// LensModel::view_fraction: frac(A), 1 - frac(A) under invView, the vendor clamp.
double view_fraction(double a) {
  const double frac_a = a - floor(a);
  const double f = inv_view ? 1.0 - frac_a : frac_a;
  return clamp(f, 1e-5LF, 0.999999LF);
}

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

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);  // (x, j), j bottom-up
  const int row = panel_size.y - 1 - pixel.y;  // LensModel's row_top_down
  // LensModel::pixel_uv: ((x + 0.5) / W, 1 - (row + 0.5) / H), v up.
  const dvec2 uv = dvec2((double(pixel.x) + 0.5LF) * inv_panel_size.x,
                         1.0LF - (double(row) + 0.5LF) * inv_panel_size.y);

  // Interlacer::sample_for, aspect fit (looking-glass.md 3.8): only the tile lookup is scaled.
  const dvec2 tile_uv = (uv - 0.5LF) * aspect_scale + 0.5LF;
  if (any(lessThan(tile_uv, dvec2(0.0))) || any(greaterThan(tile_uv, dvec2(1.0)))) {
    panel = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  // Interlacer::sample_tile's texel coordinates, the same for every channel and view.
  const dvec2 texel = clamp(tile_uv * dvec2(tile_size) - 0.5LF, dvec2(0.0), dvec2(tile_size - 1));
  const ivec2 t0 = ivec2(texel);
  const ivec2 t1 = min(t0 + 1, tile_size - 1);
  const vec2 weight = vec2(texel - dvec2(t0));

  const int pixel_class = (pixel.x & 1) + 2 * (pixel.y & 3);
  vec3 rgb;
  for (int c = 0; c < 3; ++c) {
    // LensModel::subpixel_view_fraction = view_fraction(phase(subpixel_uv(x, row, c))).
    double f = view_fraction(lens_phase(uv + subpixel_offset[pixel_class * 3 + c]));
    if (invert_views) f = 1.0 - f;
    vec3 value;
    if (!linear_blend) {
      // LensModel::view_index: floor(f V) clamped to [0, V - 1].
      const int view = clamp(int(floor(f * double(views))), 0, views - 1);
      value = sample_tile(view, t0, t1, weight);
    } else {
      // Interlacer::sample_for, linear: the two view centres (k + 0.5) / V around f, clamped
      // at the cone edges rather than wrapped.
      const double t = clamp(f * double(views) - 0.5LF, 0.0LF, double(views - 1));
      const int view_a = min(int(floor(t)), views - 1);
      const int view_b = min(view_a + 1, views - 1);
      const float weight_b = float(t - double(view_a));
      value = sample_tile(view_a, t0, t1, weight);
      if (weight_b > 0.0) {
        const vec3 b = sample_tile(view_b, t0, t1, weight);
        value += (b - value) * weight_b;
      }
    }
    rgb[c] = value[c];
  }
  // Interlacer::interlace, fringe correction (looking-glass.md 3.11): every other row darkened.
  const float fringe_gain =
      1.0 - abs(fringe) * floor(mod(float(pixel.y) + 0.5 + ceil(fringe / 2.0), 2.0));
  panel = vec4(rgb * fringe_gain, 1.0);
}
