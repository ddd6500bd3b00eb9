// The direct panel pass's compute stage over panel tiles (docs/gpu.md "The direct panel
// pass on the GPU"), for the offscreen paths (lfd render --direct, the benchmarks): each work
// group takes a kDirectPanelTileWidth x kDirectPanelTileHeight tile of the panel, an invocation
// per pixel (its three subpixel rays, direct_panel_rays.glsl, the fragment stage's arithmetic).
// The group walks the planes front to back together, in the swizzle's order (planes outer), a
// batch of kDirectPanelPlaneBatch planes at a time: the batch's factors of Eq. (u_prime)
// (two divisions each) are computed once per group, one plane per invocation, into shared
// memory, rather than once per pixel; each ray stops when its transmittance falls below
// 0.5/255 (as the CPU's), and the group stops when none of its rays is open. The planes' texels
// are read through the texture cache: a tile's rays show every view of the cone, so the window
// of a plane they read spans the cone's parallax at that depth (docs/gpu.md says why it is not
// staged in shared memory). No quilt; no rasteriser.
// PLANE_MAJOR 1 (DirectPanelPass::kComputePlaneMajor): a barrier after every plane, so every ray
// of the tile reads plane k before any reads plane k + 1 (the swizzle's order, each plane's window
// read by the whole tile at once) instead of each invocation walking the batch on its own; the
// same floats (tested), a measurement of whether the order helps (docs/gpu.md).
// Defines: BILINEAR 0|1, HW_BILINEAR 0|1 (direct_panel_rays.glsl), PANEL_FORMAT (rgba8 |
// rgba16f | rgba32f), PLANE_MAJOR 0|1.
#include "gpu/panel/shaders/direct_panel_rays.glsl"

layout(local_size_x = kDirectPanelTileWidth, local_size_y = kDirectPanelTileHeight) in;

layout(PANEL_FORMAT, binding = kDirectPanelImage) uniform writeonly image2D panel;  // rows bottom-up

shared vec3 batch_factors[kDirectPanelPlaneBatch];
shared uint any_open;

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);  // (x, j), j bottom-up
  const bool on_panel = all(lessThan(pixel, panel_size));
  // Pixels past the panel's edge take part in the group's barriers with closed rays.
  DirectRays r = direct_rays_begin(on_panel ? pixel : ivec2(0));
  if (!on_panel) r.t = vec3(0.0);
  const uint count = table.plane_count;
  for (uint first = 0u; first < count; first += kDirectPanelPlaneBatch) {
    const uint batch = min(kDirectPanelPlaneBatch, count - first);
    if (gl_LocalInvocationIndex < batch) batch_factors[gl_LocalInvocationIndex] = direct_plane_factors(first + gl_LocalInvocationIndex);
    if (gl_LocalInvocationIndex == 0u) any_open = 0u;
    barrier();  // the batch's factors and the reset flag are visible to the group
#if PLANE_MAJOR
    for (uint i = 0u; i < batch; ++i) {  // batch is the group's: uniform control flow
      if (direct_rays_open(r)) direct_rays_composite(r, batch_factors[i], int(first + i));
      barrier();  // the whole tile is done with plane i
    }
#else
    for (uint i = 0u; i < batch && direct_rays_open(r); ++i) direct_rays_composite(r, batch_factors[i], int(first + i));
#endif
    if (direct_rays_open(r)) any_open = 1u;
    barrier();  // every ray's vote is in
    if (any_open == 0u) break;  // the same value in every invocation: uniform control flow
    barrier();  // everyone has read the flag and the factors before the next batch overwrites them
  }
  if (on_panel) imageStore(panel, pixel, vec4(direct_rays_end(r, pixel), 1.0));
}
