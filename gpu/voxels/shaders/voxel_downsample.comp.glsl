// SVRaster's antialiased downsampling (voxel/antialias_downsample.cpp; PyTorch's
// interpolate(bilinear, antialias=True)): a separable triangle filter whose support widens with
// the scale, weights normalised per output pixel, from supersampled views (rgb = C + T bg,
// alpha = T) into the views' pixels of a quilt or a view image. The filter is symmetric under
// flipping an axis, so it runs on GL's bottom-up rows as the CPU does on top-down ones. At scale
// 1 it is the identity. Defines: OUT_FORMAT (rgba8 | rgba16f | rgba32f).
// One dispatch for many views: z = k is view first_view + k, read from source cell k (at
// (k % source_cols, k / source_cols) * source_size) and written into its quilt tile (tile
// (v % target_cols, v / target_cols) of tile_size, bottom-up; the view's top row on the tile's top
// row, a view larger than its tile cropped at its right and bottom, as render::place_view).
// add_background: the source holds (C, T) and each source texel becomes (C + T bg, T) before the
// filter, as the CPU composites its supersampled image before downsampling it.
#include "gpu/planes/shaders/plane_io.h"

layout(local_size_x = kPlaneGroupWidth, local_size_y = kPlaneGroupHeight) in;

layout(binding = kDownsampleSourceUnit) uniform sampler2D source;
layout(OUT_FORMAT, binding = kDownsampleTargetImage) uniform writeonly image2D target;

uniform ivec2 source_size;  // one supersampled view
uniform int source_cols;
uniform ivec2 view_size;
uniform int first_view;
uniform int target_cols;
uniform ivec2 tile_size;
uniform int add_background;
uniform vec3 background;
uniform float alpha_out;     // < 0: keep T in alpha, else write this

void taps(int o, int in_size, int out_size, out int lo, out int hi, out float center, out float support) {
  float scale = float(in_size) / float(out_size);
  support = max(1.0, scale);
  center = (float(o) + 0.5) * scale;
  lo = max(0, int(floor(center - support)));
  hi = min(in_size - 1, int(ceil(center + support)));
}

vec4 source_texel(ivec2 cell, int i, int j) {
  vec4 t = texelFetch(source, cell + ivec2(i, j), 0);
  return add_background != 0 ? vec4(t.rgb + t.a * background, t.a) : t;
}

void main() {
  ivec2 o = ivec2(gl_GlobalInvocationID.xy);
  if (o.x >= view_size.x || o.y >= view_size.y) return;
  int k = int(gl_GlobalInvocationID.z), view = first_view + k;
  ivec2 cell = ivec2(k % source_cols, k / source_cols) * source_size;
  ivec2 tile = ivec2(view % target_cols, view / target_cols) * tile_size;
  ivec2 kept = min(tile_size, view_size);  // the part of the view its tile shows
  if (o.x >= kept.x || o.y < view_size.y - kept.y) return;
  ivec2 texel = tile + ivec2(0, tile_size.y - view_size.y) + o;
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
    for (int i = x0; i <= x1; ++i) row += max(0.0, 1.0 - abs(float(i) + 0.5 - cx) / sx) * source_texel(cell, i, j);
    sum += wy * row;
  }
  vec4 v = sum / (wsum_x * wsum_y);
  imageStore(target, texel, vec4(v.rgb, alpha_out < 0.0 ? v.a : alpha_out));
}
