#pragma once
// G2LF stage 3 (paper section "Swizzle blending", Alg. 1 lines 6-12): every quilt view is
// composited from the shared sweeping planes instead of being rasterised. A view pixel's ray
// meets plane k at the reference-camera coordinate of Eq. (u_prime), where C_k and T_k are
// sampled (nearest or bilinear) and blended front to back with Eq. (alpha_blend):
// C = sum_k (prod_{m<k} T_m) c_k + (prod T) background. One plane lookup stands for a whole
// ray segment of the scene, which is why this is cheaper than rendering the views.
#include <glm/glm.hpp>

#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/sweeping_planes.hpp"
#include "util/image.hpp"

namespace lfd::render {

enum class PlaneFilter { kNearest, kBilinear };

// Writes every view's tile of `quilt` (top-down RGB float image of the layout's size).
void swizzle_blend(const SweepingPlanes& planes, const QuiltGeometry& geometry,
                   const ReferenceCamera& ref, const QuiltLayout& layout, PlaneFilter filter,
                   const glm::vec3& background, ImageF& quilt);

}  // namespace lfd::render
