#pragma once
// View-dependent colour from real SH of degree 0-3 (forward.cu computeColorFromSH;
// docs/rendering.md "The CPU reference rasterizer"): constants and signs of the reference,
// +0.5, clamped at 0 only.
#include <glm/glm.hpp>

namespace lfd::render {

// The degree-0 SH basis constant, 1 / (2 sqrt(pi)) (auxiliary.h's SH_C0). The one definition:
// gpu/shaders/sh_color.glsl carries its GLSL twin.
inline constexpr float kShC0 = 0.28209479177387814f;

// The view-independent colour of a DC coefficient: rgb = 0.5 + C0 * f_dc (before clamping).
constexpr float sh_dc_to_color(float f_dc) { return 0.5f + kShC0 * f_dc; }
inline glm::vec3 sh_dc_to_color(const glm::vec3& f_dc) { return 0.5f + kShC0 * f_dc; }

// Its inverse: the DC coefficient that shows colour `rgb`, f_dc = (rgb - 0.5) / C0.
constexpr float color_to_sh_dc(float rgb) { return (rgb - 0.5f) / kShC0; }

// `sh`: (degree+1)^2 RGB triples, coefficient-major. `dir`: unit vector from the camera centre
// to the Gaussian mean in world space.
glm::vec3 eval_sh_color(int degree, const float* sh, const glm::vec3& dir);

}  // namespace lfd::render
