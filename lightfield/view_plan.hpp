#pragma once
// Which views a light field is rendered as: the one place that decides (docs/architecture.md
// "One view plan"). From what a caller asks (a display, a view count, a cone, a camera, a size, a
// grid; each optional) and the scene, it returns the view count, the view cone, the cameras (the
// base camera and the focal plane: render::QuiltGeometry) and the quilt's tiles
// (render::QuiltLayout). `lfd render`, the viewer's frame, the demo, the benchmarks and the
// direct-panel comparisons all call plan_views.
//
// The rules, each absent field falling back in this order:
//   views      request.views, else the display's recommendation (display::quilt_for_display),
//              else util/default_display.hpp's 45;
//   cone       request.view_cone_deg, else the display's (measured when the calibration has
//              it), else the default 40 degrees; times cone_scale (the viewer's depthiness);
//   size       request.size, else the camera's own (cam.json width/height), else the display's
//              view size (view_height rows at the panel's aspect), else the camera's default;
//   camera     request.base_camera as it is (a benchmark's fixed camera; it has its size), else
//              request.camera, else the scene's framing (lightfield/scene_framing.hpp) for the
//              views' aspect (framing_aspect when given), turned by orbit_deg;
//   focal      request.focal_distance (required with a base_camera), else the distance to the
//              camera's look-at point; times focal_scale;
//   grid       request.grid, else the display's, else display::quilt_grid_for_views for the
//              views' aspect.
//   aspect     (the quilt's named view aspect, layout.aspect) the display's view aspect when the
//              views are within a pixel of it (render::snap_to_display_aspect), else the views'.
#include <optional>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "render/camera.hpp"
#include "render/camera_json.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "scene/scene.hpp"

namespace lfd::lightfield {

struct ViewRequest {
  const display::Calibration* display = nullptr;  // the display the views are for, if any
  std::optional<int> views;
  std::optional<double> view_cone_deg;
  double cone_scale = 1.0;
  std::optional<render::CameraSpec> camera;
  std::optional<render::Camera> base_camera;   // a camera already made, its size included
  float orbit_deg = 0.0f;                      // turns the scene's framing (no camera given)
  std::optional<float> framing_aspect;         // the framing's aspect instead of the views'
  std::optional<display::ViewSize> size;
  int view_height = 512;                       // rows of the display's views (no size given)
  std::optional<float> focal_distance;
  float focal_scale = 1.0f;
  std::optional<display::QuiltGrid> grid;
};

struct ViewPlan {
  std::optional<display::DisplayQuilt> display_quilt;  // what the display asked for, if one did
  int views = 0;
  double view_cone_deg = 0.0;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};

// The views a display asks for around a scene's framing, as the direct-panel benchmarks and the
// eye-photograph comparison lay them out (docs/performance.md "Direct panel rendering"): the
// display's views of `view_height` rows, the framing made for square views (as those figures
// were measured), so every side of a comparison sees the same views.
ViewRequest display_views_request(const display::Calibration& calibration, int view_height);

// A benchmark's views with no display: `views` views of `size` pixels from `camera`,
// `view_cone_deg` wide, focused at its look-at point, in the grid chosen for them.
ViewRequest benchmark_views(const render::CameraSpec& camera, display::ViewSize size, double view_cone_deg, int views);
// The same with square views of `size` x `size`.
ViewRequest square_views(const render::CameraSpec& camera, int size, double view_cone_deg, int views);

// InputError naming the request's field for views outside 1..256 or a grid too small for them.
// `scene` frames the views when the request has no camera (std::logic_error if it has neither).
ViewPlan plan_views(const ViewRequest& request, const scene::Scene* scene = nullptr);

}  // namespace lfd::lightfield
