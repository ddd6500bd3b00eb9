// SVRaster's antialiased downsampling (voxel/antialias_downsample.cpp; PyTorch's
// interpolate(bilinear, antialias=True)): a separable triangle filter whose support widens with
// the scale, weights normalised per output pixel, from the supersampled view (rgb = C + T bg,
// alpha = T) into the view's pixels of a quilt tile or view image. The filter is symmetric
// under flipping an axis, so it runs on GL's bottom-up rows as the CPU does on top-down ones.
// At scale 1 it is the identity. Defines: OUT_FORMAT (rgba8 | rgba16f | rgba32f).
#include "gpu/shaders/plane_io.h"

layout(local_size_x = kPlaneGroupWidth, local_size_y = kPlaneGroupHeight) in;

layout(binding = kDownsampleSourceUnit) uniform sampler2D source;
layout(OUT_FORMAT, binding = kDownsampleTargetImage) uniform writeonly image2D target;

uniform ivec2 source_size;
uniform ivec2 view_size;
uniform ivec2 view_origin;   // texel of the view's bottom-left pixel in the target
uniform ivec4 write_region;  // x, y, width, height in target texels: what may be written
uniform float alpha_out;     // < 0: keep T in alpha, else write this

void taps(int o, int in_size, int out_size, out int lo, out int hi, out float center, out float support) {
  float scale = float(in_size) / float(out_size);
  support = max(1.0, scale);
  center = (float(o) + 0.5) * scale;
  lo = max(0, int(floor(center - support)));
  hi = min(in_size - 1, int(ceil(center + support)));
}

void main() {
  ivec2 o = ivec2(gl_GlobalInvocationID.xy);
  if (o.x >= view_size.x || o.y >= view_size.y) return;
  ivec2 texel = view_origin + o;
  if (any(lessThan(texel, write_region.xy)) || any(greaterThanEqual(texel, write_region.xy + write_region.zw)))
    return;
  int x0, x1, y0, y1;
  float cx, sx, cy, sy;
  taps(o.x, source_size.x, view_size.x, x0, x1, cx, sx);
  taps(o.y, source_size.y, view_size.y, y0, y1, cy, sy);
  vec4 sum = vec4(0.0);
  float wsum_x = 0.0, wsum_y = 0.0;
  for (int i = x0; i <= x1; ++i) wsum_x += max(0.0, 1.0 - abs(float(i) + 0.5 - cx) / sx);
  for (int j = y0; j <= y1; ++j) {
    float wy = max(0.0, 1.0 - abs(float(j) + 0.5 - cy) / sy);
    wsum_y += wy;
    if (wy == 0.0) continue;
    vec4 row = vec4(0.0);
    for (int i = x0; i <= x1; ++i) row += max(0.0, 1.0 - abs(float(i) + 0.5 - cx) / sx) * texelFetch(source, ivec2(i, j), 0);
    sum += wy * row;
  }
  vec4 v = sum / (wsum_x * wsum_y);
  imageStore(target, texel, vec4(v.rgb, alpha_out < 0.0 ? v.a : alpha_out));
}
