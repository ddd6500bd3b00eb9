#pragma once
// Quilt camera geometry (docs/rendering.md "Cameras and quilt geometry"; paper section "Swizzle
// blending" and "Sweeping planes rendering"). Views are spread horizontally (horizontal-parallax
// displays, phi_y = 0): view j of V sits at s_j = (j + 0.5)/V - 0.5, the centre of the interlacer's
// view bin j (the paper's (j-1)/(V-1) - 1/2 puts the outer views at the bin edges instead).
#include "render/camera.hpp"
#include "util/default_display.hpp"

namespace lfd::render {

struct QuiltGeometry {
  Camera base;                 // the centre camera (paper: base camera, fov theta)
  float focal_distance = 1.0f; // D_focal: base camera to the focal (zero-parallax) plane
  float view_cone_rad = kDefaultViewConeRad;  // phi_x, the display's horizontal view cone
  int views = kDefaultViewCount;              // V

  // s_j = (j + 0.5)/V - 0.5.
  float view_position(int view) const;
  // dx_j = 2 D_focal s_j tan(phi/2), along the base camera's right axis.
  float view_offset(int view) const;
  // The same for a continuous view position s in [-1/2, 1/2] (the one definition both use): the
  // offset of the camera that a panel subpixel showing view fraction f = s + 1/2 looks from
  // (interlace/direct_panel.hpp).
  float view_offset_at(float position) const;
  // p_j = 2 s_j tan(phi/2) / tan(theta_x/2) (NDC units).
  float view_shift_ndc(int view) const;
  // The off-axis camera of view j: base moved by dx_j, same orientation, shifted principal
  // point so every principal ray meets the focal-plane centre.
  Camera view_camera(int view) const;
  // The same for a continuous view position s (view_camera(j) is this at view_position(j)): the
  // camera of an eye between two quilt views (validate/eye_photographs.hpp).
  Camera view_camera_at(float position) const;
};

// Geometry with D_focal = |look_at - position| when `focal_distance` <= 0.
QuiltGeometry make_quilt_geometry(const Camera& base, float focal_distance, float view_cone_deg,
                                  int views);

// The reference camera of the sweeping planes (paper Eqs. D_forward and theta').
struct ReferenceCamera {
  Camera camera;              // centred, at base + forward * D_forward_eff, fov theta'
  float d_forward = 0.0f;     // paper D_forward before the shift
  float d_forward_eff = 0.0f; // D_forward - D_shift: the camera's distance ahead of the base
};

// D_forward = max_k D_focal tan(phi_k/2) / (tan(phi_k/2) + tan(theta_k/2)) (phi_y = 0);
// theta'_k = 2 atan(D_focal tan(theta_k/2) / (D_focal - D_forward)), from the unshifted
// D_forward: moving the camera back by D_shift with the same angle gives a frustum that
// contains the unshifted one (the paper's near-field workaround). Resolution
// plane_scale * (W, H).
ReferenceCamera make_reference_camera(const QuiltGeometry& geometry, float d_shift, int plane_scale);
// D_forward of the unshifted reference camera: the default D_shift (back to the base camera)
// and the largest one allowed.
float forward_distance(const QuiltGeometry& geometry);

// Paper Eq. (u_prime): the reference-camera NDC coordinate where the ray of view `view`
// through its NDC coordinate u meets the plane at base-camera depth d_k. The vertical
// coordinate is the same formula with dy = 0 and theta_y, theta'_y.
float plane_coordinate_x(const QuiltGeometry& g, const ReferenceCamera& ref, int view, float u_ndc,
                         float d_k);
// The same for a camera offset dx along the right axis (continuous: view_offset_at); the
// int-view form is this with dx = view_offset(view).
float plane_coordinate_x_at(const QuiltGeometry& g, const ReferenceCamera& ref, float dx, float u_ndc,
                            float d_k);
float plane_coordinate_y(const QuiltGeometry& g, const ReferenceCamera& ref, float v_ndc, float d_k);

// Paper Eq. (gs_prefilter_fix): the 2D dilation variance (reference-camera pixels^2) that
// matches the 0.3 px^2 filter of the base camera at the focal plane.
float adaptive_filter_variance(const QuiltGeometry& g, const ReferenceCamera& ref, int plane_scale,
                               float base_variance = 0.3f);

}  // namespace lfd::render
