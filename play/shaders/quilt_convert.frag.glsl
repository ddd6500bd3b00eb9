// A decoded video frame to the quilt texture the interlacer reads (play/quilt_texture.hpp; a
// still picture is blitted there instead): rows flipped (the picture's row 0 is its top, the quilt texture's row 0 its bottom: view 0's
// tile), and YUV 4:2:0 to RGB with the stream's matrix and range (media::yuv_to_rgb_coefficients,
// the one definition, passed in as u_yuv_matrix / u_yuv_offset; its CPU twin media::yuv_to_rgb
// samples the half-size chroma planes as this linear filter does).
#include "play/shaders/quilt_convert_io.h"

in vec2 v_uv;
layout(location = 0) out vec4 out_color;
layout(binding = kQuiltPlane0Unit) uniform sampler2D u_plane0;  // Y
layout(binding = kQuiltPlane1Unit) uniform sampler2D u_plane1;  // U (Cb)
layout(binding = kQuiltPlane2Unit) uniform sampler2D u_plane2;  // V (Cr)
uniform mat3 u_yuv_matrix;
uniform vec3 u_yuv_offset;

void main() {
  const vec2 uv = vec2(v_uv.x, 1.0 - v_uv.y);  // top-down picture rows
  const vec3 yuv = vec3(texture(u_plane0, uv).r, texture(u_plane1, uv).r, texture(u_plane2, uv).r);
  out_color = vec4(clamp(u_yuv_matrix * (yuv - u_yuv_offset), 0.0, 1.0), 1.0);
}
