// The direct panel pass's fragment stage (docs/gpu.md "The direct panel pass on the
// GPU"): one fragment per panel pixel, for a framebuffer (a window's). Its three rays composite
// the planes front to back until they let no light through; the work is direct_panel_rays.glsl's,
// which the compute stage over panel tiles (direct_panel.comp.glsl) shares.
// Defines: BILINEAR 0|1, HW_BILINEAR 0|1 (direct_panel_rays.glsl).
#include "gpu/panel/shaders/direct_panel_rays.glsl"

layout(location = 0) out vec4 panel;

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);  // (x, j), j bottom-up
  DirectRays r = direct_rays_begin(pixel);
  const uint count = table.plane_count;
  for (uint k = 0u; k < count && direct_rays_open(r); ++k) direct_rays_composite(r, direct_plane_factors(k), int(k));
  panel = vec4(direct_rays_end(r, pixel), 1.0);
}
