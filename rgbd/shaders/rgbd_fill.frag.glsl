// Stage 3 of RGB-D to quilt (twin of rgbd::fill_holes, rgbd/rgbd_quilt.cpp): a pixel nothing
// landed on takes the colour of the farther (smaller depth) of its nearest covered neighbours
// left and right on its tile row, the left one on a tie, the only one at a tile's edge. Target:
// the caller's quilt, black outside the tiles, alpha 1.
#include "rgbd/shaders/rgbd_io.h"

layout(binding = kRgbdWarpedUnit) uniform sampler2D warped;  // quilt-size: colour, landed depth
uniform ivec2 tile_size;

out vec4 result;

void main() {
  const ivec2 q = ivec2(gl_FragCoord.xy);
  const vec4 here = texelFetch(warped, q, 0);
  if (here.a >= 0.0 || here.a < -1.5) {
    result = vec4(here.a >= 0.0 ? here.rgb : vec3(0.0), 1.0);
    return;
  }
  const int x0 = (q.x / tile_size.x) * tile_size.x, x1 = x0 + tile_size.x;
  int l = q.x - 1, r = q.x + 1;
  while (l >= x0 && texelFetch(warped, ivec2(l, q.y), 0).a < 0.0) --l;
  while (r < x1 && texelFetch(warped, ivec2(r, q.y), 0).a < 0.0) ++r;
  vec3 colour = vec3(0.0);
  if (l >= x0 && r < x1) {
    const vec4 left = texelFetch(warped, ivec2(l, q.y), 0), right = texelFetch(warped, ivec2(r, q.y), 0);
    colour = right.a < left.a ? right.rgb : left.rgb;
  } else if (l >= x0) {
    colour = texelFetch(warped, ivec2(l, q.y), 0).rgb;
  } else if (r < x1) {
    colour = texelFetch(warped, ivec2(r, q.y), 0).rgb;
  }
  result = vec4(colour, 1.0);
}
