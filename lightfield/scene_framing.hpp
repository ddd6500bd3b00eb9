#pragma once
// The default camera of a scene of either kind: render::frame_scene for Gaussians,
// voxel::frame_voxel_scene for voxels. `aspect` (view width / height) is used by the Gaussian
// framing.
#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "scene/scene.hpp"

namespace lfd::lightfield {

render::CameraSpec scene_framing(const scene::Scene& scene, float fov_y_deg = render::kDefaultFovYDeg,
                                 float orbit_deg = 0.0f, float aspect = 1.0f);

}  // namespace lfd::lightfield
