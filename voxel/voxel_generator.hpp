#pragma once
// Procedural sparse-voxel scenes for tests and benchmarks without a trained SVRaster model
// (`lfd scene generate --kind voxels`): the tabletop of render/scene_generator.hpp (same frame:
// COLMAP y down, ground at y = +1, objects within ~3 units of the origin, camera at z < 0)
// carved out of an octree. Only leaves that a surface passes through are kept; their level is
// `detail_level` near the objects and coarser with distance, down to a coarse outer shell
// around everything, like SVRaster's background voxels outside its inside extent.
#include <cstdint>

#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::voxel {

struct VoxelGeneratorOptions {
  int detail_level = 8;  // finest level, near the objects (root extent 16: 1/16 unit voxels)
  uint64_t seed = 1;     // colours and object placement
  int sh_degree = 1;
  void check() const;    // InputError "voxel generator options: <field>: ..."
};

scene::VoxelScene generate_voxel_scene(const VoxelGeneratorOptions& options);

// The default camera: render::frame_scene's rule on the fine (content) voxels, then moved
// toward the target until the camera and the cone's outermost views sit in empty space with no
// coarsest-level (background shell) voxel between them and the target (docs/voxels.md).
render::CameraSpec frame_voxel_scene(const scene::VoxelScene& scene, float fov_y_deg = render::kDefaultFovYDeg, float orbit_deg = 0.0f);

}  // namespace lfd::voxel
