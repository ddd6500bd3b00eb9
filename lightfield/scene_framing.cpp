#include "lightfield/scene_framing.hpp"

#include "voxel/voxel_generator.hpp"

namespace lfd::lightfield {

render::CameraSpec scene_framing(const scene::Scene& scene, float fov_y_deg, float orbit_deg, float aspect) {
  return scene.kind() == scene::SceneKind::kVoxels ? voxel::frame_voxel_scene(scene.voxels(), fov_y_deg, orbit_deg)
                                                   : render::frame_scene(scene.gaussians(), fov_y_deg, orbit_deg, aspect);
}

}  // namespace lfd::lightfield
