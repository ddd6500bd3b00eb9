// The interlacing shader's compute stage: one invocation per panel pixel, written into the
// panel texture as an image, for the offscreen paths (lfd render, lfd interlace, the benchmarks;
// docs/gpu.md "The interlacing shader"). No rasteriser, so on GPUs whose graphics pipeline is
// narrower than their compute (Hopper: docs/performance.md) the pass uses every SM. The work is
// interlace_pixel.glsl's, which the fragment stage (interlace.frag.glsl) shares.
// Defines: PANEL_FORMAT (rgba8 | rgba16f | rgba32f).
#include "gpu/panel/shaders/lens_view_io.h"
#include "gpu/panel/shaders/interlace_pixel.glsl"

layout(local_size_x = kInterlaceGroupWidth, local_size_y = kInterlaceGroupHeight) in;

layout(PANEL_FORMAT, binding = kInterlacePanelImage) uniform writeonly image2D panel;  // rows bottom-up

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);  // (x, j), j bottom-up
  if (any(greaterThanEqual(pixel, panel_size))) return;
  imageStore(panel, pixel, vec4(interlace_pixel(pixel), 1.0));
}
