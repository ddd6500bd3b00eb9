#pragma once
// A 3D Gaussian Splatting scene in memory, activated: linear scales, opacity in (0, 1),
// normalised (w, x, y, z) quaternions, SH coefficients coefficient-major with RGB innermost
// (docs/rendering.md, "Stored parameters"). Every loader produces this; every renderer
// consumes it.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace lfd::scene {

struct GaussianScene {
  int sh_degree = 0;  // 0..3; coefficients per Gaussian = (sh_degree + 1)^2
  std::vector<std::array<float, 3>> positions;  // scene units
  std::vector<std::array<float, 3>> scales;     // linear (exp of the stored log scale)
  std::vector<std::array<float, 4>> rotations;  // unit quaternion (w, x, y, z)
  std::vector<float> opacities;                 // sigmoid of the stored logit
  // size() * sh_coeffs() * 3 floats: [gaussian][coefficient][rgb]; coefficient 0 = DC.
  std::vector<float> sh;

  size_t size() const { return positions.size(); }
  int sh_coeffs() const { return (sh_degree + 1) * (sh_degree + 1); }
  const float* sh_of(size_t i) const { return sh.data() + i * size_t(sh_coeffs()) * 3; }
};

}  // namespace lfd::scene
