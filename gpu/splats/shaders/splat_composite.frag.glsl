// The background under the accumulated splats: out = C + T bg (forward.cu renderCUDA's last
// step). FROM_TEXTURE: reads (C, T) from an accumulation texture into another target (an RGBA8
// quilt tile), alpha 1. Otherwise in place through blending: the fragment is (bg, a) and the
// blend function (DST_ALPHA, ONE) adds T bg to C; alpha becomes 1 or stays T.
#include "gpu/splats/shaders/frame_io.h"

uniform vec3 background;
#ifdef FROM_TEXTURE
layout(binding = kSplatAccumulationUnit) uniform sampler2D accumulation;
uniform ivec2 viewport_origin;
#else
uniform float alpha_out;
#endif

layout(location = 0) out vec4 out_color;

void main() {
#ifdef FROM_TEXTURE
  vec4 ct = texelFetch(accumulation, ivec2(gl_FragCoord.xy) - viewport_origin, 0);
  out_color = vec4(ct.rgb + ct.a * background, 1.0);
#else
  out_color = vec4(background, alpha_out);
#endif
}
