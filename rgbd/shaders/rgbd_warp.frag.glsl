// Stage 2 of RGB-D to quilt (twin of rgbd::warp_view, rgbd/rgbd_quilt.cpp) as a gather: quilt
// pixel t of view j's tile row keeps, of the source pixels x of that row within `radius` whose
// centre x + 0.5 + shift_j(d) lands in t, the nearest (largest d): the CPU's scatter with its
// z-test, pixel for pixel. Target: quilt-size RGBA32F, rgb = colour, a = the landed depth,
// kHole (-1) where nothing landed, kOutside (-2) outside the tiles.
#include "rgbd/shaders/rgbd_io.h"

layout(binding = kRgbdSourceUnit) uniform sampler2D source;          // tile-size: colour, depth (bottom-up rows)
layout(binding = kRgbdShiftPerZUnit) uniform sampler2D shift_per_z;     // views x 1: p_j W_tile / 2 (pixels)
uniform ivec2 tile_size;
uniform ivec3 grid;         // cols, rows, views
uniform float relief_slope; // depthiness * kReliefRatio: q(d) = relief_slope (0.5 - d) + focus
uniform float focus;
uniform int radius;         // the largest |shift| in pixels, rounded up, plus one

out vec4 result;

void main() {
  const ivec2 q = ivec2(gl_FragCoord.xy);
  const ivec2 tile = q / tile_size;
  const int view = tile.y * grid.x + tile.x;
  if (tile.x >= grid.x || tile.y >= grid.y || view >= grid.z) {
    result = vec4(0.0, 0.0, 0.0, -2.0);
    return;
  }
  const int t = q.x - tile.x * tile_size.x;
  const int row = q.y - tile.y * tile_size.y;
  const float k = texelFetch(shift_per_z, ivec2(view, 0), 0).r;
  float best = -1.0;
  vec3 colour = vec3(0.0);
  const int lo = max(t - radius, 0), hi = min(t + radius, tile_size.x - 1);
  for (int x = lo; x <= hi; ++x) {
    const vec4 s = texelFetch(source, ivec2(x, row), 0);
    const float shift = k * (relief_slope * (0.5 - s.a) + focus);
    if (floor(float(x) + 0.5 + shift) == float(t) && s.a > best) {
      best = s.a;
      colour = s.rgb;
    }
  }
  result = vec4(colour, best);
}
