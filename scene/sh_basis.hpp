#pragma once
// The DC term of the SH colour as scene files store it (f_dc in a 3DGS PLY; colours in .splat,
// .ksplat, SOG and glTF are converted to it): the degree-0 basis constant and both directions.
// render/spherical_harmonics.hpp evaluates the higher degrees on top of it.
#include <glm/glm.hpp>

namespace lfd::scene {

// The degree-0 SH basis constant, 1 / (2 sqrt(pi)) (auxiliary.h's SH_C0). The one definition:
// gpu/splats/shaders/sh_color.glsl carries its GLSL twin.
inline constexpr float kShC0 = 0.28209479177387814f;

// The view-independent colour of a DC coefficient: rgb = 0.5 + C0 * f_dc (before clamping).
constexpr float sh_dc_to_color(float f_dc) { return 0.5f + kShC0 * f_dc; }
inline glm::vec3 sh_dc_to_color(const glm::vec3& f_dc) { return 0.5f + kShC0 * f_dc; }

// Its inverse: the DC coefficient that shows colour `rgb`, f_dc = (rgb - 0.5) / C0.
constexpr float color_to_sh_dc(float rgb) { return (rgb - 0.5f) / kShC0; }

}  // namespace lfd::scene
