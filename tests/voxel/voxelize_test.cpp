// lfd scene voxelize: a Gaussian's optical depth survives voxelization, neighbours agree on
// shared corners, colours come from the Gaussians' SH, empty space and the voxel budget.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include "render/spherical_harmonics.hpp"
#include "voxel/gaussian_density_field.hpp"
#include "voxel/voxel_rasterizer.hpp"
#include "voxel/voxelize.hpp"

namespace lfd::voxel {
namespace {

// Flat Gaussians (thin along z) of the given opacities and colours, at the given centres.
scene::GaussianScene disks(const std::vector<std::array<float, 3>>& centres, float opacity,
                            const std::vector<glm::vec3>& colours) {
  scene::GaussianScene s;
  s.sh_degree = 0;
  for (size_t i = 0; i < centres.size(); ++i) {
    s.positions.push_back(centres[i]);
    s.scales.push_back({0.4f, 0.4f, 0.02f});
    s.rotations.push_back({1, 0, 0, 0});
    s.opacities.push_back(opacity);
    for (int c = 0; c < 3; ++c) s.sh.push_back(scene::color_to_sh_dc(colours[i][c]));
  }
  return s;
}

// Transmittance of the voxel scene along a ray (every voxel's factor; order does not matter).
float transmittance(const scene::VoxelScene& v, const glm::vec3& origin, const glm::vec3& dir) {
  float t = 1.0f;
  for (size_t i = 0; i < v.size(); ++i) t *= 1.0f - voxel_alpha(v, i, origin, dir);
  return t;
}

TEST(GaussianDensityField, OpticalDepthThroughTheCentreIsWhatAlphaTakes) {
  const scene::GaussianScene s = disks({{0, 0, 0}}, 0.8f, {{1, 0, 0}});
  const GaussianDensityField field(s, 0.1f);
  // Midpoint sum along z through the centre, unsmoothed.
  double tau = 0.0;
  const float dt = 0.001f;
  for (float z = -0.2f; z < 0.2f; z += dt) tau += field.density({0, 0, z + 0.5f * dt}, 0.0f) * dt;
  EXPECT_NEAR(std::exp(-tau), 1.0 - 0.8, 0.01);  // within the 3-sigma cut's share
}

TEST(Voxelize, AnOpaqueDiskStaysOpaqueAndItsSurroundingsClear) {
  // Two disks so the inside cube is not degenerate; the ray crosses the first at its centre.
  const scene::GaussianScene s = disks({{0, 0, 0}, {2, 0, 0}}, 0.95f, {{1, 0, 0}, {0, 0, 1}});
  VoxelizeOptions options;
  options.max_level = 6;
  const scene::VoxelScene v = voxelize(s, options);
  const float through = transmittance(v, {0, 0, -3}, {0, 0, 1});
  // Alpha blending leaves 0.05; the fit (corner_density_fit.hpp) leaves 0.11, corners holding
  // the field's point values without it 0.17.
  EXPECT_GT(through, 0.03f);
  EXPECT_LT(through, 0.13f);
  EXPECT_GT(transmittance(v, {1, 0, -3}, {0, 0, 1}), 0.95f) << "between the disks";
  EXPECT_GT(transmittance(v, {0, 1.5f, -3}, {0, 0, 1}), 0.95f) << "beyond the disk's 3 sigma";
}

TEST(Voxelize, NeighboursAgreeOnSharedCorners) {
  const scene::GaussianScene s = disks({{0, 0, 0}, {0.7f, 0.3f, 0.5f}, {2, 0, 0}}, 0.9f, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  VoxelizeOptions options;
  options.max_level = 5;
  const scene::VoxelScene v = voxelize(s, options);
  ASSERT_GT(v.size(), 8u);
  std::map<std::tuple<uint64_t, uint64_t, uint64_t>, float> at;
  size_t shared = 0;
  for (size_t i = 0; i < v.size(); ++i)
    for (int c = 0; c < 8; ++c) {
      const int shift = scene::kMaxOctreeLevel - v.level[i];
      const auto key = std::make_tuple(uint64_t(v.octree_index[i].x + (c >> 2 & 1)) << shift,
                                       uint64_t(v.octree_index[i].y + (c >> 1 & 1)) << shift,
                                       uint64_t(v.octree_index[i].z + (c & 1)) << shift);
      const auto [it, inserted] = at.emplace(key, v.corner_density[i][size_t(c)]);
      if (!inserted) {
        ++shared;
        EXPECT_EQ(it->second, v.corner_density[i][size_t(c)]);
      }
    }
  EXPECT_GT(shared, v.size());
}

TEST(Voxelize, ColoursComeFromTheGaussiansNearby) {
  const scene::GaussianScene s = disks({{0, 0, 0}, {4, 0, 0}}, 0.9f, {{1, 0.2f, 0}, {0, 0.2f, 1}});
  VoxelizeOptions options;
  options.max_level = 5;
  const scene::VoxelScene v = voxelize(s, options);
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::vec3 c = v.voxel_center(i);
    const float* sh = v.voxel_sh(i);
    const glm::vec3 rgb = scene::sh_dc_to_color(glm::vec3(sh[0], sh[1], sh[2]));
    // Only one disk reaches each voxel: its colour exactly (the weighted mean of one), never
    // the grey of a voxel no Gaussian reaches.
    EXPECT_TRUE(c.x < 2.0f ? std::abs(rgb.r - 1.0f) < 1e-4f : std::abs(rgb.b - 1.0f) < 1e-4f) << i << " " << c.x;
  }
}

TEST(Voxelize, TheVoxelBudgetIsKept) {
  const scene::GaussianScene s = disks({{0, 0, 0}, {2, 0, 0}}, 0.9f, {{1, 0, 0}, {0, 0, 1}});
  VoxelizeOptions options;
  options.max_level = 7;
  const size_t unlimited = voxelize(s, options).size();
  options.max_voxels = unlimited / 4;
  const scene::VoxelScene v = voxelize(s, options);
  EXPECT_LE(v.size(), options.max_voxels);
  EXPECT_GT(v.size(), options.max_voxels / 8) << "the budget is spent, not wasted";
}

TEST(Voxelize, DegreeIsTruncatedOrPadded) {
  scene::GaussianScene s = disks({{0, 0, 0}, {2, 0, 0}}, 0.9f, {{1, 0, 0}, {0, 0, 1}});
  VoxelizeOptions options;
  options.max_level = 4;
  options.sh_degree = 2;
  const scene::VoxelScene v = voxelize(s, options);
  EXPECT_EQ(v.sh_degree, 2);
  for (size_t i = 0; i < v.size(); ++i)
    for (int k = 3; k < 27; ++k) EXPECT_EQ(v.voxel_sh(i)[k], 0.0f);
}

}  // namespace
}  // namespace lfd::voxel
