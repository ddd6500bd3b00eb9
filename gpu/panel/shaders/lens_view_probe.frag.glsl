// The view fraction of each channel of every pixel of a band of panel rows, as lens_view.glsl
// (#included) computes it: for measuring the shaders' single precision against LensModel over
// whole panels (gpu::view_fractions_on_gpu, tests/gpu/gl_lens_view_test.cpp).
#include "gpu/panel/shaders/lens_view.glsl"

uniform int first_j;  // the band's lowest panel row, bottom-up

layout(location = 0) out vec4 fractions;

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy) + ivec2(0, first_j);
  fractions = vec4(lens_view_fraction(pixel, 0), lens_view_fraction(pixel, 1), lens_view_fraction(pixel, 2), 1.0);
}
