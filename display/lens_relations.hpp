#pragma once
// The physical relations of a slanted lenticular display, each defined once (docs/display-model.md;
// the shader terms as LKG-Toolkit's Calibration.cs computes them). The lens model, the interlacer,
// the optics simulator, the calibration solver and its coarse start, validation and the demo all
// call these. They are templates so the solver can differentiate through them with ceres::Jet;
// nothing here needs Ceres: T only has to support arithmetic and the unqualified sqrt/tan found
// by ADL.
#include <cmath>
#include <numbers>

namespace lfd::display {

// The value of a plain number or of a Jet (its `.a`), for branches on the sign.
inline double scalar_part(double x) { return x; }
template <typename Jet>
auto scalar_part(const Jet& x) -> decltype(x.a) { return x.a; }

// The shader terms of the lens phase A(u, v) = (u + v tilt) pitch' - center:
//   pitch' = pitch * (W / DPI) * cos(atan(1 / slope))   lens periods across the screen width,
//            measured horizontally; cos(atan(1/s)) = |s| / sqrt(1 + s^2) for either sign,
//   tilt   = H / (W * slope), negated by flipImageX      phase change per unit v relative to u.
struct ScreenGeometry {
  double width_px = 0, height_px = 0, dpi = 0;
  bool flip_image_x = false;
};

template <typename T>
struct ShaderTerms {
  T pitch_periods;  // pitch'
  T tilt;
};

template <typename T>
ShaderTerms<T> shader_terms(const ScreenGeometry& g, const T& pitch_lpi, const T& slope) {
  using std::sqrt;
  const T abs_slope = scalar_part(slope) < 0 ? T(-slope) : slope;
  ShaderTerms<T> t{pitch_lpi * (g.width_px / g.dpi) * abs_slope / sqrt(T(1) + slope * slope),
                   T(g.height_px) / (T(g.width_px) * slope)};
  if (g.flip_image_x) t.tilt = -t.tilt;
  return t;
}

// The inverse: the visual.json pitch (lenticules per inch) and slope that give pitch' and tilt.
struct PitchSlope {
  double pitch_lpi, slope;
};
PitchSlope pitch_slope_from_shader_terms(const ScreenGeometry& g, double pitch_periods, double tilt);

// The lens slant from vertical in degrees, atan(1 / slope) (signed as the slope), and back.
// Perturb a slant through these, not the slope: the slope is run over rise.
inline double slant_deg_of_slope(double slope) {
  return std::atan(1.0 / slope) * 180.0 / std::numbers::pi;
}
inline double slope_of_slant_deg(double slant_deg) {
  return 1.0 / std::tan(slant_deg * std::numbers::pi / 180.0);
}

// k = 1 / (2 tan(viewCone / 2)): view fraction per unit of tan(theta), the horizontal angle
// off the display normal.
template <typename T>
T fraction_per_tan(const T& view_cone_deg) {
  using std::tan;
  return T(0.5) / tan(view_cone_deg * T(std::numbers::pi / 360.0));
}
// Its inverse: the view cone in degrees whose k this is.
double view_cone_from_fraction_per_tan(double k);

// The lens lines' tilt: lines of equal phase A = (u + v tilt) pitch' - center run along
// x + y * line_tilt = const in panel pixels (or metres: square pixels), y up as v, with
// line_tilt = tilt * W / H = 1 / slope, negated by flipImageX (the model negates the tilt and
// leaves u alone, so the physical lines lean the other way). A viewer moving along a line sees
// nothing change: the lens has no power along its axis.
template <typename T>
T line_tilt(const ScreenGeometry& g, const T& tilt) {
  return tilt * (g.width_px / g.height_px);
}

// The seen view fraction, unwrapped: a lens at panel point P sends view fraction f toward a
// viewer at C (display frame, metres, y up, z toward the viewer) with
//   f_seen = 0.5 + ((Cx - Px) + (Cy - Py) line_tilt) / (Cz - Pz) / (2 tan(viewCone / 2)).
// Only the offset across the lens lines counts (a lenticular lens has no power along them): the
// vertical offset is worth line_tilt times as much as a horizontal one, which over the height of a
// screen seen from half a metre is several hundredths of a period (a form with Cx - Px alone leaves
// it out: docs/display-model.md "What a viewer sees"). f_seen < 0 or >= 1 lies outside the cone,
// where the neighbouring lens repeats the views: wrap it with wrap_fraction(). seen_fraction_k()
// takes k = fraction_per_tan(viewCone) instead of the cone (the coarse start fits k directly).
template <typename T, typename L>
T seen_fraction_k(const T& dx_m, const T& dy_m, const T& dz_m, const L& line_tilt,
                  const T& fraction_per_tan_k) {
  return T(0.5) + (dx_m + dy_m * line_tilt) / dz_m * fraction_per_tan_k;
}
template <typename T, typename L>
T seen_fraction(const T& dx_m, const T& dy_m, const T& dz_m, const L& line_tilt,
                const T& view_cone_deg) {
  return seen_fraction_k(dx_m, dy_m, dz_m, line_tilt, fraction_per_tan(view_cone_deg));
}
// The same from the direction tan_x = dx / dz, tan_y = dy / dz directly.
template <typename T, typename L>
T seen_fraction_of_tan(const T& tan_x, const T& tan_y, const L& line_tilt,
                       const T& view_cone_deg) {
  return T(0.5) + (tan_x + tan_y * line_tilt) * fraction_per_tan(view_cone_deg);
}
// The horizontal direction tan(theta) in which a view fraction f leaves the display toward a
// viewer level with the lens (dy = 0); a viewer above it sees f at tan(theta) - tan_y line_tilt.
inline double tan_of_seen_fraction(double f, double view_cone_deg) {
  return (f - 0.5) / fraction_per_tan(view_cone_deg);
}

// The cover layer: a flat slab (Looking Glass' acrylic block, a cover glass) of thickness t and
// refractive index n between the lens array (the plane z = 0) and the viewer. It bends no
// direction a lens sends out (the view fraction belongs to the direction in air), but a ray
// leaving lens point P toward a viewer at C crosses the slab at the steeper in-slab angle,
// sin(theta_air) = n sin(theta_slab), so it reaches C from a different direction than the
// straight line P -> C. Paraxially the panel appears t (1 - 1/n) nearer (apparent_shift_m());
// off axis the exact ray differs by terms in tan^2(theta), which for cameras 25-30 degrees to
// the side of a 16" screen reach a hundredth of a period (docs/display-model.md, "The cover
// layer"), twice the center bar: cover_seen_distance() is exact. thickness_m = 0: a bare panel.
struct CoverLayer {
  double thickness_m = 0.0;
  double refractive_index = 1.49;  // PMMA (acrylic) near 589 nm
  bool present() const { return thickness_m > 0.0; }
  // The paraxial apparent shift of the panel toward the viewer, t (1 - 1/n).
  double apparent_shift_m() const { return thickness_m * (1.0 - 1.0 / refractive_index); }
};

// tan(theta_slab) / tan(theta_air) for a ray whose direction in air has tan^2 = tan2_air
// (|(dx, dy)| / dz squared): 1 / sqrt(n^2 + (n^2 - 1) tan^2). The in-slab tangent keeps the
// direction's azimuth (refraction stays in the plane of incidence), so the ratio applies to
// tan_x and tan_y alike.
template <typename T>
T cover_tan_ratio(const T& tan2_air, double n) {
  using std::sqrt;
  return T(1) / sqrt(T(n * n) + T(n * n - 1.0) * tan2_air);
}

// The distance D such that the ray from lens point P to a viewer at offset (dx, dy, dz) = C - P
// (dz from the lens plane, dz > thickness) leaves the cover in the air direction
// (tan_x, tan_y) = (dx, dy) / D. Pass D as seen_fraction()'s dz: with no cover D = dz, and
// paraxially D = dz - t (1 - 1/n). The lateral offset splits into the air path and the slab
// path, |d| = tan_air ((dz - t) + t ratio(tan_air^2)), so D = (dz - t) + t ratio((|d| / D)^2):
// a fixed point whose map contracts by at most (t / D) (n^2 - 1) tan^2 / n^3 (0.006 for a 2 cm
// block seen from 0.45 m at 30 degrees); six steps from the paraxial D leave under 1e-9 m for
// any viewer inside +-60 degrees. Differentiable (ceres::Jet) through the iteration.
// The thickness may be an unknown too (a Jet: the solver estimates it, docs/calibration.md
// "The cover layer"); t = 0 gives D = dz.
template <typename T>
T cover_seen_distance(const T& dx, const T& dy, const T& dz, const T& thickness_m, double n) {
  const T lateral2 = dx * dx + dy * dy;
  T d = dz - thickness_m * (1.0 - 1.0 / n);
  for (int i = 0; i < 6; ++i)
    d = dz - thickness_m + thickness_m * cover_tan_ratio(T(lateral2 / (d * d)), n);
  return d;
}
template <typename T>
T cover_seen_distance(const T& dx, const T& dy, const T& dz, const CoverLayer& cover) {
  if (!cover.present()) return dz;
  return cover_seen_distance(dx, dy, dz, T(cover.thickness_m), cover.refractive_index);
}

// The seen view fraction through a cover: seen_fraction() with the distance the cover makes.
template <typename T, typename L>
T seen_fraction_through_cover(const T& dx_m, const T& dy_m, const T& dz_m, const CoverLayer& cover,
                              const L& line_tilt, const T& view_cone_deg) {
  return seen_fraction(dx_m, dy_m, cover_seen_distance(dx_m, dy_m, dz_m, cover), line_tilt,
                       view_cone_deg);
}

// Into [0, 1): outside the cone the neighbouring lens repeats the views.
inline double wrap_fraction(double f) { return f - std::floor(f); }

// The lens content shift: the lens covering a panel point P shows the viewer the content at
// the point Q of the same lens whose phase shows f_seen (frac(A(Q)) = c with c = 1 - f_seen
// under invView, else f_seen). Averaged over the lens, Q - P = (c - 1/2) lens periods along
// the row: the content a camera sees is displaced by that much from the point it looks at,
// and jumps by a whole lens where c wraps. Returned in lens periods, in [-1/2, 1/2).
inline double lens_content_shift(double f_seen, bool inv_view) {
  const double c = inv_view ? 1.0 - f_seen : f_seen;
  return c - std::floor(c) - 0.5;
}

}  // namespace lfd::display
