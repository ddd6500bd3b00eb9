// One quad per sorted visible splat (instanced, glDrawArraysIndirect, a 4-vertex strip).
// For LAYERED, the GL_ARB_shader_viewport_layer_array extension line comes before every
// declaration (Mesa refuses it later), so before the #includes.
//
// Coverage: the reference evaluates a splat on every pixel of the 16x16 tiles its rectangle
// touches, but a pixel changes the image only where alpha = min(0.99, o exp(power)) >= 1/255,
// i.e. inside the ellipse d^T conic d <= 2 ln(255 o). The quad is that ellipse's bounding box
// (x half-width sqrt(2 ln(255 o) Sigma_xx), with Sigma = conic^-1), one pixel wider for float
// rounding, intersected with the tile rectangle and the image: every pixel the reference blends
// is covered (exact), and the quad is smaller than both the tile rectangle (up to 15 px wider per
// side) and the 3-sigma square (o < 0.99 shrinks it; per-axis extents instead of lambda_max).
#ifdef LAYERED
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/splat_record.glsl"

layout(std430, binding = kSplatRecordsBinding) readonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kSplatValuesBinding) readonly buffer SortedIds { uint sorted_ids[]; };
#ifdef LAYERED
layout(std430, binding = kSplatLayersBinding) readonly buffer Layers { uint layers[]; };
#endif

uniform ivec2 image_size;  // the view's size in pixels; the viewport maps it to the target

flat out vec2 v_mean;
flat out vec3 v_conic;
flat out float v_opacity;
flat out vec3 v_color;

const int kTileSize = 16;

void main() {
  SplatRecord r = records[sorted_ids[gl_InstanceID]];
#ifdef LAYERED
  gl_Layer = int(layers[gl_InstanceID]);
#endif
  vec2 mean = r.mean_depth_opacity.xy;
  float opacity = r.mean_depth_opacity.w;
  vec3 conic = r.conic_radius.xyz;
  v_mean = mean;
  v_conic = conic;
  v_opacity = opacity;
  v_color = r.color.rgb;

  float k2 = 2.0 * log(255.0 * opacity);  // squared Mahalanobis radius of alpha = 1/255
  float det = conic.x * conic.z - conic.y * conic.y;
  vec2 extent = sqrt(max(k2, 0.0) * vec2(conic.z, conic.x) / det) + 1.0;
  // Clamped as floats first: a huge extent must not overflow the conversion to int.
  vec2 limit_lo = vec2(-1.0), limit_hi = vec2(image_size);
  ivec2 lo = max(r.rect.xy * kTileSize, ivec2(clamp(ceil(mean - extent), limit_lo, limit_hi)));
  ivec2 hi = min(min(r.rect.zw * kTileSize, image_size) - 1, ivec2(clamp(floor(mean + extent), limit_lo, limit_hi)));
  if (!(k2 > 0.0) || !(det > 0.0) || any(greaterThan(lo, hi))) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // nothing to draw: outside the clip volume
    return;
  }
  // Pixel edges in image coordinates (row 0 = top): columns lo.x .. hi.x + 1, rows likewise;
  // GL's y runs up, so image row y lies at window row H - 1 - y.
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  vec2 edge = mix(vec2(lo), vec2(hi + 1), corner);
  gl_Position = vec4(edge.x / float(image_size.x) * 2.0 - 1.0, 1.0 - edge.y / float(image_size.y) * 2.0, 0.0, 1.0);
}
