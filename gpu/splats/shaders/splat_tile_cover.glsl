// Which tiles a projected Gaussian's keys go to (gpu/splats/gl_splat_tile_raster.hpp; docs/gpu.md "The compute
// tile rasterizer"): the tiles of its rectangle (the reference's getRect, 3 sigma) whose pixel
// centres it may give alpha >= 1/255, the compositing's threshold. alpha = o exp(-q / 2) with
// q = d^T conic d, so a pixel counts only where q <= 2 ln(255 o): an ellipse that shrinks with
// the opacity (a splat with o < 1/255 covers nothing). The test is exact for the tile's pixel
// centres up to a margin (0.02 in q, 0.01 px), so it drops only tiles the reference skips pixel by
// pixel: the images do not change, the lists get shorter.
#include "gpu/splats/shaders/splat_record.glsl"

// The smallest q over the segment from `a` to `b` (d = mean - p), q(d) = x^2 cx + 2 x y cy + y^2 cz.
float q_of(vec3 conic, vec2 d) { return conic.x * d.x * d.x + 2.0 * conic.y * d.x * d.y + conic.z * d.y * d.y; }

bool splat_covers_tile(SplatRecord r, ivec2 tile) {
  vec2 mean = r.mean_depth_opacity.xy;
  vec3 conic = r.conic_radius.xyz;
  float opacity = r.mean_depth_opacity.w;
  float limit = 2.0 * log(255.0 * opacity) + 0.02;
  if (!(limit >= 0.0)) return false;
  if (!(conic.x > 0.0) || !(conic.z > 0.0)) return true;  // not an ellipse: keep the rectangle
  vec2 lo = vec2(tile * 16) - 0.01, hi = vec2(tile * 16 + 15) + 0.01;
  if (all(greaterThanEqual(mean, lo)) && all(lessThanEqual(mean, hi))) return true;
  // Outside the rectangle the minimum lies on its boundary: per edge, the unconstrained minimum
  // along it, clamped to the edge.
  float best = 1e30;
  for (int e = 0; e < 2; ++e) {
    float dx = mean.x - (e == 0 ? lo.x : hi.x);  // vertical edges: dx fixed
    float dy = clamp(-conic.y * dx / conic.z, mean.y - hi.y, mean.y - lo.y);
    best = min(best, q_of(conic, vec2(dx, dy)));
    float ey = mean.y - (e == 0 ? lo.y : hi.y);  // horizontal edges: dy fixed
    float ex = clamp(-conic.y * ey / conic.x, mean.x - hi.x, mean.x - lo.x);
    best = min(best, q_of(conic, vec2(ex, ey)));
  }
  return best <= limit;
}
