#include "lightfield/view_plan.hpp"

#include <stdexcept>

#include <glm/glm.hpp>

#include "lightfield/scene_framing.hpp"
#include "render/default_camera.hpp"
#include "render/per_view_quilt.hpp"
#include "util/default_display.hpp"
#include "util/error.hpp"

namespace lfd::lightfield {
namespace {

// The views' size when the request fixes it: its own, or the display's unless the camera has one.
std::optional<display::ViewSize> fixed_size(const ViewRequest& r, const std::optional<display::DisplayQuilt>& quilt) {
  if (r.size) return r.size;
  const bool camera_sized = r.camera && (r.camera->width || r.camera->height);
  if (quilt && !camera_sized) return display::view_size_for_display(*quilt, r.view_height);
  return std::nullopt;
}

}  // namespace

ViewRequest display_views_request(const display::Calibration& calibration, int view_height) {
  ViewRequest r;
  r.display = &calibration;
  r.view_height = view_height;
  r.framing_aspect = 1.0f;
  return r;
}

ViewRequest square_views(const render::CameraSpec& camera, int size, double view_cone_deg, int views) {
  return benchmark_views(camera, display::ViewSize{size, size}, view_cone_deg, views);
}

ViewRequest benchmark_views(const render::CameraSpec& camera, display::ViewSize size, double view_cone_deg, int views) {
  ViewRequest r;
  r.camera = camera;
  r.size = size;
  r.view_cone_deg = view_cone_deg;
  r.views = views;
  return r;
}

ViewPlan plan_views(const ViewRequest& r, const scene::Scene* scene) {
  ViewPlan plan;
  if (r.display) plan.display_quilt = display::quilt_for_display(*r.display, r.views);
  plan.views = plan.display_quilt ? plan.display_quilt->views : r.views.value_or(kDefaultViewCount);
  if (plan.views < 1 || plan.views > 256) throw_input_error("views: {} is outside 1..256", plan.views);
  plan.view_cone_deg = r.view_cone_deg.value_or(plan.display_quilt ? plan.display_quilt->view_cone_deg
                                                                   : kDefaultViewConeDeg) *
                       r.cone_scale;

  render::Camera base;
  float focal = 0.0f;
  if (r.base_camera) {
    if (!r.focal_distance) throw std::logic_error("plan_views: a base camera needs its focal distance");
    base = *r.base_camera;
    focal = *r.focal_distance * r.focal_scale;
  } else {
    const std::optional<display::ViewSize> size = fixed_size(r, plan.display_quilt);
    render::CameraSpec spec;
    if (r.camera) {
      spec = *r.camera;
    } else {
      if (scene == nullptr) throw std::logic_error("plan_views: neither a camera nor a scene to frame");
      const float aspect = r.framing_aspect.value_or(size ? float(size->width) / float(size->height) : 1.0f);
      spec = scene_framing(*scene, render::kDefaultFovYDeg, r.orbit_deg, aspect);
    }
    base = size ? render::camera_from_spec(spec, size->width, size->height) : render::camera_from_spec(spec);
    focal = r.focal_distance.value_or(glm::length(spec.look_at - spec.position)) * r.focal_scale;
  }
  plan.geometry = render::make_quilt_geometry(base, focal, float(plan.view_cone_deg), plan.views);

  const display::QuiltGrid grid = r.grid                 ? *r.grid
                                  : plan.display_quilt ? plan.display_quilt->grid
                                                       : display::quilt_grid_for_views(plan.views, double(base.width) / base.height);
  if (grid.cols < 1 || grid.rows < 1 || grid.cols * grid.rows < plan.views)
    throw_input_error("grid: {}x{} tiles cannot hold {} views", grid.cols, grid.rows, plan.views);
  plan.layout = render::make_quilt_layout(plan.geometry, grid.cols, grid.rows);
  // The quilt names the display's view aspect, not its tiles' rounded one (the interlacer would
  // pillarbox those by a column); the camera's when there is no display.
  if (plan.display_quilt)
    plan.layout.aspect =
        render::snap_to_display_aspect(plan.layout.aspect, base.height, plan.display_quilt->view_aspect);
  return plan;
}

}  // namespace lfd::lightfield
