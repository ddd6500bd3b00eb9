#include "render/spherical_harmonics.hpp"

#include <algorithm>

namespace lfd::render {
namespace {
constexpr float kC1 = 0.4886025119029199f;
constexpr float kC2[] = {1.0925484305920792f, -1.0925484305920792f, 0.31539156525252005f,
                         -1.0925484305920792f, 0.5462742152960396f};
constexpr float kC3[] = {-0.5900435899266435f, 2.890611442640554f, -0.4570457994644658f,
                         0.3731763325901154f, -0.4570457994644658f, 1.445305721320277f,
                         -0.5900435899266435f};
}  // namespace

glm::vec3 eval_sh_color(int degree, const float* sh_raw, const glm::vec3& dir) {
  const auto sh = [sh_raw](int k) { return glm::vec3(sh_raw[3 * k], sh_raw[3 * k + 1], sh_raw[3 * k + 2]); };
  glm::vec3 result = scene::kShC0 * sh(0);
  if (degree > 0) {
    const float x = dir.x, y = dir.y, z = dir.z;
    result = result - kC1 * y * sh(1) + kC1 * z * sh(2) - kC1 * x * sh(3);
    if (degree > 1) {
      const float xx = x * x, yy = y * y, zz = z * z;
      const float xy = x * y, yz = y * z, xz = x * z;
      result = result + kC2[0] * xy * sh(4) + kC2[1] * yz * sh(5) +
               kC2[2] * (2.0f * zz - xx - yy) * sh(6) + kC2[3] * xz * sh(7) +
               kC2[4] * (xx - yy) * sh(8);
      if (degree > 2) {
        result = result + kC3[0] * y * (3.0f * xx - yy) * sh(9) + kC3[1] * xy * z * sh(10) +
                 kC3[2] * y * (4.0f * zz - xx - yy) * sh(11) +
                 kC3[3] * z * (2.0f * zz - 3.0f * xx - 3.0f * yy) * sh(12) +
                 kC3[4] * x * (4.0f * zz - xx - yy) * sh(13) + kC3[5] * z * (xx - yy) * sh(14) +
                 kC3[6] * x * (xx - 3.0f * yy) * sh(15);
      }
    }
  }
  result += 0.5f;
  return glm::max(result, glm::vec3(0.0f));
}

}  // namespace lfd::render
