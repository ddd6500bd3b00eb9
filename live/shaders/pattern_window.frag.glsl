// Panel pixel (x, y) shows pattern texel (x, H-1-y): the pattern's row 0 is the panel's top
// row, GL's window row 0 its bottom. texelFetch: one texel per pixel, no filtering, no scaling,
// and 8-bit values survive the unorm round trip exactly (v / 255 * 255 = v). gpu::Program puts
// the #version line first; PatternWindow binds the pattern to kPatternUnit.
#include "live/shaders/pattern_window_io.h"

layout(binding = kPatternUnit) uniform sampler2D pattern;
out vec4 color;

void main() {
  ivec2 size = textureSize(pattern, 0);
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  color = vec4(texelFetch(pattern, ivec2(pixel.x, size.y - 1 - pixel.y), 0).rgb, 1.0);
}
