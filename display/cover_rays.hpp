#pragma once
// Rays through the cover layer, in the display frame (metres, lens plane z = 0, y up, viewer at
// z > 0): the two directions in which the simulator and registration trace them. Both rest on
// the one relation in lens_relations.hpp (cover_tan_ratio, cover_seen_distance): refraction at
// the cover's flat front face z = t keeps a ray's azimuth and turns tan(theta_air) into
// tan(theta_slab) = tan(theta_air) cover_tan_ratio(tan^2).
#include "display/lens_relations.hpp"

namespace lfd::display {

struct Point3 {
  double x = 0, y = 0, z = 0;
};

// A camera ray from C along `dir` (dir.z < 0, toward the panel): the lens-plane point it
// reaches and its direction in air from that point back toward C (tan_x, tan_y), which is
// what picks the view fraction. With no cover: the straight line's panel point.
struct PanelHit {
  double x = 0, y = 0, tan_x = 0, tan_y = 0;
};
inline PanelHit panel_hit_through_cover(const Point3& c, const Point3& dir, const CoverLayer& cover) {
  const double tan_x = dir.x / dir.z, tan_y = dir.y / dir.z;  // back toward C
  const double to_front = (cover.thickness_m - c.z) / dir.z;    // C to the cover's front face
  const double slab =
      cover.thickness_m * cover_tan_ratio(tan_x * tan_x + tan_y * tan_y, cover.refractive_index);
  return {c.x + to_front * dir.x - slab * tan_x, c.y + to_front * dir.y - slab * tan_y, tan_x,
          tan_y};
}

// Where the light from lens point P (z = 0) toward a viewer at C leaves the cover's front face:
// a camera sees P there (the point registration must project). With no cover: P itself.
inline Point3 cover_exit_point(const Point3& p, const Point3& c, const CoverLayer& cover) {
  if (!cover.present()) return p;
  const double dx = c.x - p.x, dy = c.y - p.y, dz = c.z - p.z;
  const double d = cover_seen_distance(dx, dy, dz, cover);
  const double tan_x = dx / d, tan_y = dy / d;
  const double slab =
      cover.thickness_m * cover_tan_ratio(tan_x * tan_x + tan_y * tan_y, cover.refractive_index);
  return {p.x + slab * tan_x, p.y + slab * tan_y, p.z + cover.thickness_m};
}

}  // namespace lfd::display
