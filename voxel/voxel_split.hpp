#pragma once
// A voxel split into its 8 octree children (docs/voxels.md, "V2LF": V2LF may split a voxel that
// straddles a chunk boundary, "which keeps the density field identical"). A child's corner
// densities are the parent's scene::trilinear field at the child's corners; scene::trilinear
// interpolation restricted to an axis-aligned sub-box is again scene::trilinear there, so every
// point has the same raw density (and so the same activated density) before and after. SH is
// copied: SVRaster evaluates it along the direction to the voxel centre, so a child's
// view-dependent colour differs slightly.
#include <cstddef>

#include <glm/glm.hpp>

#include "scene/voxel_scene.hpp"

namespace lfd::voxel {

// Appends voxel `i` of `scene`'s 8 children to `out` (same sh_degree): child c sits at octree
// index 2 index + (bit 2, bit 1, bit 0) of c, one level deeper. Returns the first child's index
// in `out`. `scene` and `out` may be the same scene. Requires level < scene::kMaxOctreeLevel.
size_t append_children(const scene::VoxelScene& scene, size_t i, scene::VoxelScene& out);

// The raw (pre-activation) density of voxel `i` at world point `p` (clamped into the voxel).
float raw_density_at(const scene::VoxelScene& scene, size_t i, const glm::vec3& p);

}  // namespace lfd::voxel
