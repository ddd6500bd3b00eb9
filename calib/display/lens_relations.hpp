#pragma once
// The physical relations of a slanted lenticular display, each defined once (DESIGN section 4,
// reference/looking-glass.md 3.1). The lens model, the interlacer, the optics simulator, the
// calibration solver and its coarse start, validation and the demo all call these. They are
// templates so the solver can differentiate through them with ceres::Jet; nothing here needs
// Ceres: T only has to support arithmetic and the unqualified sqrt/tan found by ADL.
#include <cmath>
#include <numbers>

namespace lfd::calib {

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
// Only the offset across the lens lines counts (reference/display-optics.md 2.1 item 6): the
// vertical offset is worth line_tilt times as much as a horizontal one, which over the height
// of a screen seen from half a metre is several hundredths of a period (DESIGN section 4's
// first formula, Cx - Px alone, left it out). f_seen < 0 or >= 1 lies outside the cone, where
// the neighbouring lens repeats the views: wrap it with wrap_fraction(). seen_fraction_k()
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

}  // namespace lfd::calib
