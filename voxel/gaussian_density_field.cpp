// The extinction field of a Gaussian scene (see the header for the mass of a Gaussian).
#include "voxel/gaussian_density_field.hpp"

#include <algorithm>
#include <cmath>

#include "render/preprocess.hpp"

namespace lfd::voxel {

namespace {
constexpr float kTwoPi = 6.283185307179586f;
constexpr float kMaxBinnedCells = 4096.0f;  // larger 3-sigma boxes go to the searched-always list
constexpr int kKeyBias = 1 << 20;
}  // namespace

float gaussian_optical_depth(float opacity) {
  // 3DGS caps alpha at 0.99 (forward.cu), so no Gaussian is more than that opaque.
  return -std::log(1.0f - std::clamp(opacity, 0.0f, 0.99f));
}

GaussianDensityField::GaussianDensityField(const scene::GaussianScene& scene, float cell_size)
    : cell_size_(cell_size) {
  const size_t n = scene.size();
  means_.resize(n);
  covariances_.resize(n);
  mass_.resize(n);
  min_scale_.resize(n);
  support_.resize(n);
  first_cell_.resize(n);
  for (size_t g = 0; g < n; ++g) {
    const auto& p = scene.positions[g];
    means_[g] = {p[0], p[1], p[2]};
    origin_ = g == 0 ? means_[g] : glm::min(origin_, means_[g]);
  }
  for (size_t g = 0; g < n; ++g) {
    covariances_[g] = render::covariance_3d(scene.scales[g], 1.0f, scene.rotations[g]);
    std::array<float, 3> s = scene.scales[g];
    std::sort(s.begin(), s.end());
    min_scale_[g] = s[0];
    mass_[g] = gaussian_optical_depth(scene.opacities[g]) * kTwoPi * s[1] * s[2];
    support_[g] = 3.0f * axis_sigma(g);
    const glm::ivec3 lo = cell_of(means_[g] - support_[g]), hi = cell_of(means_[g] + support_[g]);
    first_cell_[g] = lo;
    const glm::vec3 cells = glm::vec3(hi - lo + 1);
    if (cells.x * cells.y * cells.z > kMaxBinnedCells) {
      everywhere_.push_back(uint32_t(g));
      continue;
    }
    for (int cz = lo.z; cz <= hi.z; ++cz)
      for (int cy = lo.y; cy <= hi.y; ++cy)
        for (int cx = lo.x; cx <= hi.x; ++cx) cells_[key({cx, cy, cz})].push_back(uint32_t(g));
  }
}

glm::vec3 GaussianDensityField::axis_sigma(size_t g) const {
  const glm::mat3& c = covariances_[g];
  return glm::sqrt(glm::max(glm::vec3(c[0][0], c[1][1], c[2][2]), 0.0f));
}

glm::ivec3 GaussianDensityField::cell_of(const glm::vec3& p) const {
  const glm::vec3 c = glm::floor((p - origin_) / cell_size_);
  return glm::ivec3(glm::clamp(c, glm::vec3(-kKeyBias + 1), glm::vec3(kKeyBias - 1)));
}

uint64_t GaussianDensityField::key(const glm::ivec3& c) {
  return uint64_t(c.x + kKeyBias) | uint64_t(c.y + kKeyBias) << 21 | uint64_t(c.z + kKeyBias) << 42;
}

float GaussianDensityField::contribution(size_t g, const glm::vec3& x, float variance) const {
  const glm::mat3 cov = covariances_[g] + glm::mat3(variance);
  const float det = glm::determinant(cov);
  if (!(det > 0.0f)) return 0.0f;
  const glm::vec3 d = x - means_[g];
  const float q = glm::dot(d, glm::inverse(cov) * d);
  if (q > 9.0f) return 0.0f;  // 3 sigma, as 3DGS cuts its splats
  return mass_[g] * std::exp(-0.5f * q) / (std::pow(kTwoPi, 1.5f) * std::sqrt(det));
}

float GaussianDensityField::density(const glm::vec3& x, float smoothing) const {
  float sum = 0.0f;
  for_each_contribution(x, smoothing, [&](uint32_t, float d) { sum += d; });
  return sum;
}

}  // namespace lfd::voxel
