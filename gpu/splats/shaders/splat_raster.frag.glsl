// The reference's per-pixel rules (forward.cu renderCUDA; docs/rendering.md "The CPU reference
// rasterizer"): pixel (i, j) of the view is evaluated at exactly (i, j), row 0 = top.
// The output is premultiplied (c alpha, alpha); the blend function
// (DST_ALPHA, ONE | ZERO, ONE_MINUS_SRC_ALPHA) on a target holding (C, T) then does
// C += c alpha T and T *= 1 - alpha, front to back (gpu/splats/gl_splat_raster.hpp).
flat in vec2 v_mean;
flat in vec3 v_conic;
flat in float v_opacity;
flat in vec3 v_color;

uniform ivec2 image_size;
uniform vec2 viewport_origin;  // window coordinates of the view's bottom-left corner

layout(location = 0) out vec4 out_color;

void main() {
  vec2 window = gl_FragCoord.xy - viewport_origin;  // pixel centres at .5
  vec2 pixel = vec2(window.x - 0.5, float(image_size.y) - window.y - 0.5);
  vec2 d = v_mean - pixel;
  float power = -0.5 * (v_conic.x * d.x * d.x + v_conic.z * d.y * d.y) - v_conic.y * d.x * d.y;
  if (power > 0.0) discard;
  float alpha = min(0.99, v_opacity * exp(power));
  if (alpha < 1.0 / 255.0) discard;
  out_color = vec4(v_color * alpha, alpha);
}
