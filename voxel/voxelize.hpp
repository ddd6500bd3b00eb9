#pragma once
// A 3DGS scene turned into SVRaster sparse voxels (`lfd scene voxelize`; docs/voxels.md, "Test
// content from Gaussian scenes"), so real Gaussian scenes give voxel scenes of realistic structure.
//   - Octree: SVRaster's inside cube (the centres' 0.5-99.5% quantiles, 10% margin), doubled
//     until it holds every centre (at most 4 outside levels, like SVRaster's background), and
//     split breadth-first wherever a cell holds, in Gaussians thinner than the cell, more mass
//     of the Gaussian density field than a finest-level voxel of optical depth
//     `split_optical_depth` (mass over the finest cross-section), up to `max_level` and, with `max_voxels`, heaviest cells first until the
//     count would pass it. Leaves whose own mean optical depth (mass over their cross-section)
//     is below `keep_optical_depth` are empty space and dropped.
//   - Densities: the field (voxel/gaussian_density_field.hpp) at every grid point, smoothed at
//     the size of the finest leaf that has the point as a corner, divided by SVRaster's step
//     scale and stored through the inverse of scene::exp_linear_11. One value per grid point, so
//     neighbours agree on the corners they share.
//   - Colour: the least-squares SH of the Gaussians' colours seen through the voxel, each
//     weighted by its density at the voxel centre. SH bases are orthonormal on the sphere, so
//     that least-squares fit is the weighted mean of the coefficients (truncated to the output
//     degree): no system to solve.
#include <cstddef>

#include "scene/gaussian_scene.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::voxel {

struct VoxelizeOptions {
  int max_level = 8;                 // finest level counted in the inside cube (edge = inside / 2^level)
  size_t max_voxels = 0;             // 0: no limit
  int sh_degree = -1;                // -1: the scene's
  float split_optical_depth = 0.02f;
  float keep_optical_depth = 1e-3f;
  void check() const;                // InputError "voxelize options: <field>: ..."
};

struct VoxelizeReport {
  size_t gaussians_outside = 0;  // centres outside the root cube (only their tails are voxelized)
  int outside_levels = 0;        // root = inside cube * 2^outside_levels
  size_t grid_points = 0;
  int finest_level = 0;
};

scene::VoxelScene voxelize(const scene::GaussianScene& scene, const VoxelizeOptions& options,
                    VoxelizeReport* report = nullptr);

}  // namespace lfd::voxel
