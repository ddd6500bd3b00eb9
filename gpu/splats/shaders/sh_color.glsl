// View-dependent colour from SH (forward.cu computeColorFromSH; docs/rendering.md), the GLSL twin
// of render/spherical_harmonics.cpp: one definition for every GL pass that evaluates SH (the splat
// preprocess, the voxel raster), #included by them. The coefficients of primitive g are
// (degree+1)^2 RGB triples, coefficient-major, packed into sh_stride vec4s per primitive
// (gpu/splats/gl_scene.hpp, gpu/voxels/gl_voxel_scene.hpp).
#include "gpu/splats/shaders/frame_io.h"

layout(std430, binding = kSceneShBinding) readonly buffer Sh { vec4 sh[]; };
uniform int sh_degree;
uniform int sh_stride;  // vec4s per primitive

// SH coefficient k (RGB) of primitive g: floats 3k..3k+2 of its vec4-packed block.
vec3 sh_coefficient(uint g, int k) {
  uint base = g * uint(sh_stride);
  int f = 3 * k;
  return vec3(sh[base + uint(f >> 2)][f & 3], sh[base + uint((f + 1) >> 2)][(f + 1) & 3],
              sh[base + uint((f + 2) >> 2)][(f + 2) & 3]);
}

// Section 6 (forward.cu computeColorFromSH), as render/spherical_harmonics.cpp.
vec3 sh_color(uint g, vec3 dir) {
  const float C0 = 0.28209479177387814;  // kShC0 in render/spherical_harmonics.hpp
  const float C1 = 0.4886025119029199;
  const float C2[5] = float[5](1.0925484305920792, -1.0925484305920792, 0.31539156525252005,
                               -1.0925484305920792, 0.5462742152960396);
  const float C3[7] = float[7](-0.5900435899266435, 2.890611442640554, -0.4570457994644658,
                               0.3731763325901154, -0.4570457994644658, 1.445305721320277,
                               -0.5900435899266435);
  vec3 result = C0 * sh_coefficient(g, 0);
  if (sh_degree > 0) {
    float x = dir.x, y = dir.y, z = dir.z;
    result = result - C1 * y * sh_coefficient(g, 1) + C1 * z * sh_coefficient(g, 2) -
             C1 * x * sh_coefficient(g, 3);
    if (sh_degree > 1) {
      float xx = x * x, yy = y * y, zz = z * z;
      float xy = x * y, yz = y * z, xz = x * z;
      result = result + C2[0] * xy * sh_coefficient(g, 4) + C2[1] * yz * sh_coefficient(g, 5) +
               C2[2] * (2.0 * zz - xx - yy) * sh_coefficient(g, 6) +
               C2[3] * xz * sh_coefficient(g, 7) + C2[4] * (xx - yy) * sh_coefficient(g, 8);
      if (sh_degree > 2) {
        result = result + C3[0] * y * (3.0 * xx - yy) * sh_coefficient(g, 9) +
                 C3[1] * xy * z * sh_coefficient(g, 10) +
                 C3[2] * y * (4.0 * zz - xx - yy) * sh_coefficient(g, 11) +
                 C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy) * sh_coefficient(g, 12) +
                 C3[4] * x * (4.0 * zz - xx - yy) * sh_coefficient(g, 13) +
                 C3[5] * z * (xx - yy) * sh_coefficient(g, 14) +
                 C3[6] * x * (xx - 3.0 * yy) * sh_coefficient(g, 15);
      }
    }
  }
  result += 0.5;
  return max(result, vec3(0.0));
}
