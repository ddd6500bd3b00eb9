#include "render/quilt_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace lfd::render {

float QuiltGeometry::view_position(int view) const {
  return (float(view) + 0.5f) / float(views) - 0.5f;
}

float QuiltGeometry::view_offset(int view) const { return view_offset_at(view_position(view)); }

float QuiltGeometry::view_offset_at(float position) const {
  return 2.0f * focal_distance * position * std::tan(0.5f * view_cone_rad);
}

namespace {
// p(s) = 2 s tan(phi/2) / tan(theta_x/2): the principal-point shift of the camera at view position s.
float shift_ndc_at(const QuiltGeometry& g, float position) {
  return 2.0f * position * std::tan(0.5f * g.view_cone_rad) / g.base.tan_half_fov_x();
}
}  // namespace

float QuiltGeometry::view_shift_ndc(int view) const { return shift_ndc_at(*this, view_position(view)); }

Camera QuiltGeometry::view_camera(int view) const { return view_camera_at(view_position(view)); }

Camera QuiltGeometry::view_camera_at(float position) const {
  Camera c = base;
  c.position_world = base.position_world + view_offset_at(position) * base.right();
  c.shift_x_ndc = base.shift_x_ndc + shift_ndc_at(*this, position);
  return c;
}

QuiltGeometry make_quilt_geometry(const Camera& base, float focal_distance, float view_cone_deg,
                                  int views) {
  if (views < 1) throw_input_error("quilt geometry: view count {} must be positive", views);
  if (!(focal_distance > 0.0f)) throw_input_error("quilt geometry: focal distance must be positive");
  if (!(view_cone_deg >= 0.0f && view_cone_deg < 170.0f))
    throw_input_error("quilt geometry: view cone {} deg must lie in [0, 170)", view_cone_deg);
  QuiltGeometry g;
  g.base = base;
  g.focal_distance = focal_distance;
  g.view_cone_rad = view_cone_deg * float(M_PI) / 180.0f;
  g.views = views;
  return g;
}

ReferenceCamera make_reference_camera(const QuiltGeometry& g, float d_shift, int plane_scale) {
  if (plane_scale < 1) throw_input_error("reference camera: plane scale must be >= 1");
  const double df = g.focal_distance;
  const double tphi_x = std::tan(0.5 * g.view_cone_rad), tphi_y = 0.0;
  const double tth_x = g.base.tan_half_fov_x(), tth_y = g.base.tan_half_fov_y();
  const double d_forward =
      std::max(df * tphi_x / (tphi_x + tth_x), df * tphi_y / (tphi_y + tth_y));
  ReferenceCamera ref;
  ref.d_forward = float(d_forward);
  ref.d_forward_eff = float(d_forward - d_shift);
  Camera c = g.base;
  c.position_world = g.base.position_world + ref.d_forward_eff * g.base.forward();
  c.fov_x_rad = float(2.0 * std::atan(df * tth_x / (df - d_forward)));
  c.fov_y_rad = float(2.0 * std::atan(df * tth_y / (df - d_forward)));
  c.width = g.base.width * plane_scale;
  c.height = g.base.height * plane_scale;
  c.shift_x_ndc = 0.0f;
  c.shift_y_ndc = 0.0f;
  ref.camera = c;
  return ref;
}

float forward_distance(const QuiltGeometry& geometry) { return make_reference_camera(geometry, 0.0f, 1).d_forward; }

float plane_coordinate_x(const QuiltGeometry& g, const ReferenceCamera& ref, int view, float u_ndc,
                         float d_k) {
  return plane_coordinate_x_at(g, ref, g.view_offset(view), u_ndc, d_k);
}

float plane_coordinate_x_at(const QuiltGeometry& g, const ReferenceCamera& ref, float dx, float u_ndc,
                            float d_k) {
  return (dx * (g.focal_distance - d_k) / g.focal_distance + d_k * g.base.tan_half_fov_x() * u_ndc) /
         ((d_k - ref.d_forward_eff) * ref.camera.tan_half_fov_x());
}

float plane_coordinate_y(const QuiltGeometry& g, const ReferenceCamera& ref, float v_ndc, float d_k) {
  return (d_k * g.base.tan_half_fov_y() * v_ndc) / ((d_k - ref.d_forward_eff) * ref.camera.tan_half_fov_y());
}

float adaptive_filter_variance(const QuiltGeometry& g, const ReferenceCamera& ref, int plane_scale,
                               float base_variance) {
  const float ratio = g.focal_distance * g.base.tan_half_fov_x() /
                      ((g.focal_distance - ref.d_forward_eff) * ref.camera.tan_half_fov_x()) *
                      float(plane_scale);
  return base_variance * ratio * ratio;
}

}  // namespace lfd::render
