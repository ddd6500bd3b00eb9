// Each equation of the quilt geometry checked against an independent construction
// (ray/plane intersections in world space).
#include <cmath>

#include <gtest/gtest.h>

#include "render/quilt_geometry.hpp"

namespace lfd::render {
namespace {

QuiltGeometry test_geometry(int views = 45, float cone_deg = 40.0f) {
  const Camera base = make_look_at_camera({0.5f, 1.0f, 4.0f}, {0.2f, 0.1f, -1.0f}, {0, 1, 0}, 0.7f, 96, 64);
  return make_quilt_geometry(base, glm::length(glm::vec3(0.2f, 0.1f, -1.0f) - glm::vec3(0.5f, 1.0f, 4.0f)),
                             cone_deg, views);
}

// World point of view `view`'s pixel ray (NDC u, v) at base-camera depth d.
glm::vec3 ray_point(const QuiltGeometry& g, int view, float u, float v, float d) {
  const Camera c = g.view_camera(view);
  const float x_over_z = (u - c.shift_x_ndc) * c.tan_half_fov_x();
  const float y_over_z = (v - c.shift_y_ndc) * c.tan_half_fov_y();
  return c.position_world + d * (c.forward() + x_over_z * c.right() + y_over_z * c.down());
}

TEST(QuiltGeometry, ViewPositionsAreBinCentres) {
  const QuiltGeometry g = test_geometry(4);
  // s_j = (j + 0.5) / V - 0.5 with V = 4: -0.375 and 0.375.
  EXPECT_FLOAT_EQ(g.view_position(0), -0.375f);
  EXPECT_FLOAT_EQ(g.view_position(3), 0.375f);
  EXPECT_LT(g.view_offset(0), 0.0f);  // view 0 is the leftmost camera
}

TEST(QuiltGeometry, OuterViewsSpanTheViewCone) {
  // Bin edges s = +-0.5 would sit at +-phi/2 seen from the focal-plane centre.
  const QuiltGeometry g = test_geometry(45, 40.0f);
  const float edge = 2.0f * g.focal_distance * 0.5f * std::tan(0.5f * g.view_cone_rad);
  EXPECT_NEAR(std::atan(edge / g.focal_distance), 0.5f * g.view_cone_rad, 1e-6f);
  EXPECT_NEAR(g.view_offset(44) - g.view_offset(0), 2.0f * edge * 44.0f / 45.0f, 1e-5f);
}

TEST(QuiltGeometry, FocalPlanePointsProjectToTheSamePixelInEveryView) {
  const QuiltGeometry g = test_geometry();
  const Camera& base = g.base;
  // Points on the focal plane (depth D_focal in front of the base camera) at several offsets.
  for (float a : {-0.3f, 0.0f, 0.25f})
    for (float b : {-0.2f, 0.15f}) {
      const glm::vec3 p = base.position_world + g.focal_distance * base.forward() + a * base.right() + b * base.down();
      const glm::vec2 ref = base.project_px(p);
      for (int j : {0, 7, 22, 44}) {
        const glm::vec2 px = g.view_camera(j).project_px(p);
        EXPECT_NEAR(px.x, ref.x, 2e-3f) << "view " << j;
        EXPECT_NEAR(px.y, ref.y, 2e-3f) << "view " << j;
      }
    }
  // Off the focal plane the views disagree (parallax), behind it a point moves against the camera motion.
  const glm::vec3 far = base.position_world + 2.0f * g.focal_distance * base.forward();
  EXPECT_LT(g.view_camera(0).project_px(far).x + 1.0f, g.view_camera(44).project_px(far).x);
}

TEST(QuiltGeometry, ReferenceCameraApexIsWhereTheOuterFrustumEdgesMeet) {
  const QuiltGeometry g = test_geometry(45, 40.0f);
  const ReferenceCamera ref = make_reference_camera(g, 0.0f, 1);
  // Edge ray of the extreme camera at s = -0.5 (bin edge) through the right edge of the focal
  // window crosses the axis at D_forward.
  const double df = g.focal_distance, tphi = std::tan(0.5 * g.view_cone_rad), tth = g.base.tan_half_fov_x();
  const double cam_x = -df * tphi, window_x = df * tth;
  const double z_cross = -cam_x / ((window_x - cam_x) / df);
  EXPECT_NEAR(ref.d_forward, z_cross, 1e-4);
  // theta': the reference frustum passes through the focal window edges.
  EXPECT_NEAR((df - ref.d_forward) * ref.camera.tan_half_fov_x(), window_x, 1e-4);
  EXPECT_NEAR((df - ref.d_forward) * ref.camera.tan_half_fov_y(), df * g.base.tan_half_fov_y(), 1e-4);
  EXPECT_NEAR(glm::dot(ref.camera.position_world - g.base.position_world, g.base.forward()), ref.d_forward, 1e-4);
}

TEST(QuiltGeometry, ShiftMovesTheReferenceCameraBackAndKeepsItsAngle) {
  const QuiltGeometry g = test_geometry();
  const ReferenceCamera a = make_reference_camera(g, 0.0f, 2), b = make_reference_camera(g, 0.5f, 2);
  EXPECT_NEAR(b.d_forward_eff, a.d_forward - 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(a.camera.fov_x_rad, b.camera.fov_x_rad);
  EXPECT_EQ(b.camera.width, 2 * g.base.width);
}

TEST(QuiltGeometry, PlaneCoordinateMatchesRayPlaneIntersection) {
  const QuiltGeometry g = test_geometry();
  for (float shift : {0.0f, 0.4f}) {
    const ReferenceCamera ref = make_reference_camera(g, shift, 1);
    for (int j : {0, 13, 44})
      for (float u : {-0.9f, 0.1f, 0.7f})
        for (float v : {-0.5f, 0.6f})
          for (float d : {0.6f * g.focal_distance, g.focal_distance, 1.8f * g.focal_distance}) {
            const glm::vec3 p = ray_point(g, j, u, v, d);
            const glm::vec2 expected = ref.camera.project_ndc(p);
            EXPECT_NEAR(plane_coordinate_x(g, ref, j, u, d), expected.x, 1e-4f);
            EXPECT_NEAR(plane_coordinate_y(g, ref, v, d), expected.y, 1e-4f);
          }
  }
}

TEST(QuiltGeometry, AdaptiveFilterMatchesThePixelFootprintOnTheFocalPlane) {
  const QuiltGeometry g = test_geometry();
  const ReferenceCamera ref = make_reference_camera(g, 0.3f, 2);
  // Base-camera pixel width on the focal plane over the reference camera's, squared, times 0.3.
  const float base_px = 2.0f * g.focal_distance * g.base.tan_half_fov_x() / float(g.base.width);
  const float ref_px = 2.0f * (g.focal_distance - ref.d_forward_eff) * ref.camera.tan_half_fov_x() /
                       float(ref.camera.width);
  const float ratio = base_px / ref_px;
  EXPECT_NEAR(adaptive_filter_variance(g, ref, 2), 0.3f * ratio * ratio, 1e-5f);
  // Without a shift the reference pixels on the focal plane equal the base ones at P_s = 1.
  const ReferenceCamera r1 = make_reference_camera(g, 0.0f, 1);
  EXPECT_NEAR(adaptive_filter_variance(g, r1, 1), 0.3f, 1e-5f);
}

}  // namespace
}  // namespace lfd::render
