// lightfield/display_views.hpp: the display's quilt, the views' size, the scene's framing.
#include "lightfield/display_views.hpp"

#include <glm/glm.hpp>

#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "render/per_view_quilt.hpp"

namespace lfd::lightfield {

DisplayViews views_for_display(const display::Calibration& calibration, const LightFieldScene& scene,
                               int view_height, std::optional<int> views) {
  DisplayViews v;
  v.quilt = display::quilt_for_display(calibration, views);
  v.size = display::view_size_for_display(v.quilt, view_height);
  const render::CameraSpec spec = scene.framing(render::kDefaultFovYDeg);
  const render::Camera base = render::camera_from_spec(spec, v.size.width, v.size.height);
  v.geometry = render::make_quilt_geometry(base, glm::length(spec.look_at - spec.position),
                                           float(v.quilt.view_cone_deg), v.quilt.views);
  v.layout = render::make_quilt_layout(v.geometry, v.quilt.grid.cols, v.quilt.grid.rows);
  return v;
}

}  // namespace lfd::lightfield
