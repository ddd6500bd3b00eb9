#pragma once
// A camera that frames a scene when the user gives none: it looks along the scene's +z axis
// (the forward axis of COLMAP-trained 3DGS scenes) with -y up (COLMAP y points down), from far
// enough that the sphere holding 90% of the centres fits the vertical field of view (but inside an
// enclosing background shell, if there is one); the target (and so
// the quilt's focal plane) is the centre of the 25-75% box. `orbit_deg` turns the camera about the up axis
// through the centre.
#include "render/camera_json.hpp"
#include "render/gaussian_scene.hpp"

namespace lfd::render {

// The default camera's vertical field of view (not the display's view cone, also 40 degrees).
inline constexpr float kDefaultFovYDeg = 40.0f;

CameraSpec frame_scene(const GaussianScene& scene, float fov_y_deg = kDefaultFovYDeg, float orbit_deg = 0.0f);

}  // namespace lfd::render
