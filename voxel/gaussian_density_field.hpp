#pragma once
// A 3DGS scene read as a volume: each Gaussian becomes an extinction density (1/scene unit)
// with its own covariance, scaled so that a ray through its centre along its thinnest axis (a
// flat Gaussian seen face on, how a surface is mostly seen) loses what alpha blending takes
// there: tau = -ln(1 - opacity). Its total mass (the integral of the density) is then
// tau * 2 pi s_a s_b, s_a and s_b its two larger scales: optical depth times footprint area.
// Used by `lfd scene voxelize` (voxel/voxelize.hpp), which samples the field smoothed at each
// voxel's size so that small Gaussians between corners keep their mass.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "scene/gaussian_scene.hpp"

namespace lfd::voxel {

// The optical depth through one Gaussian's centre that alpha blending implies; opacity is
// clamped at 3DGS's 0.99 alpha cap.
float gaussian_optical_depth(float opacity);

class GaussianDensityField {
 public:
  // `cell_size`: edge of the hash grid that finds the Gaussians near a point (about the
  // finest voxel size). Gaussians whose 3-sigma box is huge go to a list searched always.
  GaussianDensityField(const scene::GaussianScene& scene, float cell_size);

  size_t size() const { return means_.size(); }
  float mass(size_t g) const { return mass_[g]; }
  const glm::vec3& mean(size_t g) const { return means_[g]; }
  float min_scale(size_t g) const { return min_scale_[g]; }  // its thinnest axis's sigma
  // Standard deviation of Gaussian g along each axis (sqrt of the covariance's diagonal).
  glm::vec3 axis_sigma(size_t g) const;
  // Half the edge of Gaussian g's axis-aligned 3-sigma box.
  const glm::vec3& support(size_t g) const { return support_[g]; }

  // The density at x smoothed by a scene::trilinear hat of half-width `smoothing` (a voxel's edge):
  // the hat is replaced by the Gaussian of its variance, smoothing^2 / 6 per axis, so each
  // Gaussian's covariance grows by that and its mass is kept.
  float density(const glm::vec3& x, float smoothing) const;

  // Calls visit(g, density of g at x) for every Gaussian that contributes at x (same smoothing).
  template <typename Visit>
  void for_each_contribution(const glm::vec3& x, float smoothing, Visit&& visit) const;

 private:
  glm::ivec3 cell_of(const glm::vec3& p) const;
  static uint64_t key(const glm::ivec3& c);
  float contribution(size_t g, const glm::vec3& x, float variance) const;

  float cell_size_;
  glm::vec3 origin_{0.0f};
  std::vector<glm::vec3> means_;
  std::vector<glm::mat3> covariances_;
  std::vector<float> mass_;
  std::vector<float> min_scale_;
  std::vector<glm::vec3> support_;
  std::vector<glm::ivec3> first_cell_;  // the lowest hash cell of each Gaussian's box
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
  std::vector<uint32_t> everywhere_;  // Gaussians too large to bin
};

template <typename Visit>
void GaussianDensityField::for_each_contribution(const glm::vec3& x, float smoothing, Visit&& visit) const {
  const float variance = smoothing * smoothing / 6.0f;
  for (uint32_t g : everywhere_)
    if (const float d = contribution(g, x, variance); d > 0.0f) visit(g, d);
  // The hat's reach (3 sigma of variance h^2/6 is 1.23 h) plus the Gaussian's own 3-sigma box:
  // a Gaussian binned in several cells is counted in the first cell both boxes share, so each
  // is visited once without per-query bookkeeping.
  const glm::vec3 reach(1.23f * smoothing);
  const glm::ivec3 lo = cell_of(x - reach), hi = cell_of(x + reach);
  for (int cz = lo.z; cz <= hi.z; ++cz)
    for (int cy = lo.y; cy <= hi.y; ++cy)
      for (int cx = lo.x; cx <= hi.x; ++cx) {
        const auto it = cells_.find(key({cx, cy, cz}));
        if (it == cells_.end()) continue;
        for (uint32_t g : it->second) {
          const glm::ivec3 first = glm::max(first_cell_[g], lo);
          if (first != glm::ivec3(cx, cy, cz)) continue;
          if (const float d = contribution(g, x, variance); d > 0.0f) visit(g, d);
        }
      }
}

}  // namespace lfd::voxel
