// The interlacing shader's fragment stage: one fragment per panel pixel, for a framebuffer (a
// window's; docs/gpu.md "The interlacing shader"). The work is interlace_pixel.glsl's, which the
// compute stage (interlace.comp.glsl) shares.
#include "gpu/panel/shaders/interlace_pixel.glsl"

layout(location = 0) out vec4 panel;

void main() { panel = vec4(interlace_pixel(ivec2(gl_FragCoord.xy)), 1.0); }
