#pragma once
// View-dependent colour from real SH of degree 0-3 (forward.cu computeColorFromSH;
// docs/rendering.md "The CPU reference rasterizer"): constants and signs of the reference,
// +0.5, clamped at 0 only.
#include <glm/glm.hpp>

#include "scene/sh_basis.hpp"

namespace lfd::render {

// `sh`: (degree+1)^2 RGB triples, coefficient-major. `dir`: unit vector from the camera centre
// to the Gaussian mean in world space.
glm::vec3 eval_sh_color(int degree, const float* sh, const glm::vec3& dir);

}  // namespace lfd::render
