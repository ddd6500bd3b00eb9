#pragma once
// Shared corner densities fitted to per-voxel targets (lfd scene voxelize). SVRaster samples a
// voxel at the midpoint of the ray's chord (K = 1) and interpolates raw densities, which
// scene::exp_linear_11 activates exponentially below 1.1: a voxel whose corners hold the field's point
// values (one dense, seven clear) sees their geometric, not arithmetic, mean and loses most of
// its optical depth (a disk of alpha 0.95 came out at 0.83). So the raw corner values are fitted,
// by sparse linear least squares (Eigen's LSCG), to make each voxel's mean raw value (its
// centre's) the raw value of its mean density, held to the point values with equal weight (the
// disk: 0.89); voxel rows weighted more reach 0.95 but fatten silhouettes, every voxel a
// surface grazes turning uniformly dense (docs/voxels.md). One unknown per grid point:
// neighbours still share their corners.
#include <array>
#include <cstdint>
#include <vector>

namespace lfd::voxel {

struct CornerFitOptions {
  float point_weight = 1.0f;  // pull towards the point value, against a voxel row's 1
  int max_iterations = 300;
  float tolerance = 1e-4f;
};

// corner_point[v][c]: grid point index of voxel v's corner c; voxel_target_raw[v]: the raw value
// each voxel's corner mean should have; point_raw: per grid point, the starting guess and the
// regulariser's target. Returns the fitted raw value per grid point.
std::vector<float> fit_corner_densities(const std::vector<std::array<uint32_t, 8>>& corner_point,
                                        const std::vector<float>& voxel_target_raw,
                                        const std::vector<float>& point_raw, const CornerFitOptions& options = {});

}  // namespace lfd::voxel
