#pragma once
// The sweeping planes composited along single rays of any camera offset (docs/rendering.md
// "Direct panel rendering"): the swizzle blend of render/swizzle_blend.hpp for one ray at a time,
// with the view offset continuous instead of one of V views. The direct panel pass
// (interlace/direct_panel.hpp) asks it for one colour channel per panel subpixel, in the
// direction that subpixel is seen from. The plane coordinate is Eq. (u_prime) through
// plane_coordinate_x_at / plane_coordinate_y (render/quilt_geometry.hpp), the sampling and the
// front-to-back blend those of the swizzle (nearest or bilinear, empty outside the plane, a ray
// stops below half an 8-bit step of transmittance).
#include <vector>

#include <glm/glm.hpp>

#include "render/quilt_geometry.hpp"
#include "render/sweeping_planes.hpp"
#include "render/swizzle_blend.hpp"

namespace lfd::render {

// One ray of a row: camera offset dx (QuiltGeometry::view_offset_at), horizontal base-camera NDC
// u, and the colour channel wanted (0 R, 1 G, 2 B). A row's rays come in order of u
// (non-decreasing), which lets a plane skip the rays that cannot reach its non-empty columns.
struct PlaneRay {
  float dx = 0, u_ndc = 0;
  int channel = 0;
};

class PlaneRays {
 public:
  // The planes must outlive this object.
  PlaneRays(const SweepingPlanes& planes, const QuiltGeometry& geometry, const ReferenceCamera& ref,
            PlaneFilter filter, const glm::vec3& background);

  // The largest |dx| of the rays is `max_abs_dx` (the view cone's edge).
  // The composited channel of every ray of one row of base-camera NDC v_ndc_top_down
  // ((2 y + 1) / H - 1 for view row y, rows top-down as the planes): out[i] for rays[i].
  void composite_row(float v_ndc_top_down, float max_abs_dx, const std::vector<PlaneRay>& rays,
                     std::vector<float>& out) const;

 private:
  // Per plane: Eq. (u_prime) as u' = dx parallax + u scale_x, v' = v scale_y.
  struct PlaneMap {
    float parallax, scale_x, scale_y;
  };
  template <typename Texels, bool kBilinear>
  void composite(const Texels& tex, float v_ndc, float max_abs_dx, const std::vector<PlaneRay>& rays,
                 std::vector<float>& out) const;

  const SweepingPlanes& planes_;
  std::vector<PlaneMap> maps_;
  PlaneFilter filter_;
  glm::vec3 background_;
};

}  // namespace lfd::render
