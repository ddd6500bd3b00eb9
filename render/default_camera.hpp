#pragma once
// A camera that frames a scene's content when the user gives none (docs/rendering.md,
// "Default camera"). The content is scene::content_bounds(): the box of the Gaussians that carry the
// opacity (opacity-weighted 5-95% per axis). The camera uses the 3DGS/COLMAP convention of
// trained captures, y down and z forward: up is -y, and it looks along +z, raised by
// kDefaultElevationDeg so that a ground or table top is seen from above rather than edge-on.
// It looks at the centre of the box, so the zero-parallax (focal) plane of a quilt passes
// through the content; it stands back just far enough that the Gaussians holding kFramedOpacity
// of the content's opacity (those with opacity >= kContentMinOpacity) lie inside the view,
// shrunk by kFrameMargin on every side, for a view of `aspect` (width / height). Inside an
// enclosing background shell (the 99% distance of the centres far beyond the content) it stays
// inside the shell. `orbit_deg` turns the camera about the up axis.
#include "render/camera_json.hpp"
#include "scene/gaussian_scene.hpp"

namespace lfd::render {

// The default camera's vertical field of view (not the display's view cone, also 40 degrees).
inline constexpr float kDefaultFovYDeg = 40.0f;
// How far above the horizontal (the scene's x-z plane) the default camera looks down.
inline constexpr float kDefaultElevationDeg = 20.0f;
// The share of the half-width and half-height kept free around the content box.
inline constexpr float kFrameMargin = 0.08f;
// The share of the content's opacity the default camera keeps in view, and the opacity from
// which a Gaussian counts as content.
inline constexpr double kFramedOpacity = 0.97;
inline constexpr float kContentMinOpacity = 0.1f;

CameraSpec frame_scene(const scene::GaussianScene& scene, float fov_y_deg = kDefaultFovYDeg,
                       float orbit_deg = 0.0f, float aspect = 1.0f);

}  // namespace lfd::render
