#pragma once
// A sparse-voxel radiance field in SVRaster's representation (Sun et al., "Sparse Voxels
// Rasterization", CVPR 2025; docs/voxels.md, "The representation"): octree leaves only, each with
// its integer octree coordinates and level, raw (pre-activation) densities at its 8 corners and SH
// colour. Structure of arrays, like GaussianScene, so a GPU port can upload each array as it is.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace lfd::scene {

// SVRaster's octree is at most 16 levels deep (its 48-bit octpath: 3 bits per level).
inline constexpr int kMaxOctreeLevel = 16;

struct VoxelScene {
  glm::vec3 scene_center{0.0f};  // centre of the root cell
  float scene_extent = 1.0f;     // edge of the root cell; a level-L voxel's edge is extent * 2^-L
  int sh_degree = 0;             // 0-3
  float supersampling = 1.5f;    // ss: rendered at ss times the size, then downsampled
  int samples_per_voxel = 1;     // K: density samples along the ray inside each voxel
  glm::vec3 background{0.0f};    // what the ray sees after the last voxel (C + T * background)

  // Per voxel. Integer coordinates at its own level: 0 <= index < 2^level per axis.
  std::vector<glm::u32vec3> octree_index;
  std::vector<uint8_t> level;
  // Raw densities at the corners; corner i sits at (x, y, z) = (bit 2, bit 1, bit 0) of i.
  std::vector<std::array<float, 8>> corner_density;
  // (sh_degree + 1)^2 RGB triples per voxel, coefficient-major (3DGS constants).
  std::vector<float> sh;

  size_t size() const { return level.size(); }
  int sh_coeffs() const { return (sh_degree + 1) * (sh_degree + 1); }
  void resize(size_t count);  // every per-voxel array, for the current sh_degree

  float voxel_size(size_t i) const;        // scene_extent * 2^-level
  glm::vec3 voxel_min(size_t i) const;     // the corner with the smallest coordinates
  glm::vec3 voxel_center(size_t i) const;
  const float* voxel_sh(size_t i) const { return sh.data() + i * size_t(sh_coeffs()) * 3; }
  float* voxel_sh(size_t i) { return sh.data() + i * size_t(sh_coeffs()) * 3; }
};

// SVRaster's density activation exp_linear_11: x above 1.1, else exp(x / 1.1 - 1 + ln 1.1),
// which meets the line at x = 1.1 with the same value and slope.
float exp_linear_11(float raw_density);
// Its inverse: the raw density whose activation is `density` (> 0); what a density field is
// stored as (lfd scene voxelize, SVRaster's own init).
float inverse_exp_linear_11(float density);

// Trilinear interpolation of the 8 corner values at local position `t` in [0, 1]^3.
float trilinear(const std::array<float, 8>& corners, const glm::vec3& t);

// Checks every field and voxel (levels, coordinates inside the level's grid, finite values,
// sizes of the arrays); throws InputError("<name>: <field>: ...") naming the first bad one.
void check_voxel_scene(const VoxelScene& scene, const std::string& name);

}  // namespace lfd::scene
