#pragma once
// Coarse start (docs/calibration.md section 3.3). With the nominal model far off (1 % pitch, 0.5
// degree slant, any center) the decoded phase wraps many times across the screen (moire), so
// a local solver started at the nominal values would lock onto a wrong wrap. But per position
// the phase is a plane in (u, v) plus the small correction field:
//   psi = alpha + beta_u u + beta_v v + s w,   with (from the phase of section 3.2)
//   beta_u = -W_m k / Cz + s (P'_true - P'_nom),
//   beta_v = -W_m T k / Cz + s (T_true P'_true - T_nom P'_nom)   (vertical parallax: H_m L = W_m T),
//   alpha  = 1/2 + ((Cx + W_m / 2) + (Cy + H_m / 2) L) k / Cz + s (center_nom - center_true),
//   k = 1/(2 tan(cone/2)), L = line_tilt = T W / H,
// so the dominant 2D frequency of exp(2 pi i psi) gives (beta_u, beta_v) and its phase alpha;
// from the planes of all positions follow pitch, slope, center and (with positions at
// different distances) the view cone.
#include <vector>

#include "calib/solver/lens_solver.hpp"

namespace lfd::calib {

struct PhasePlane {
  double alpha = 0, beta_u = 0, beta_v = 0;
  double coherence = 0;  // |sum exp(2 pi i (psi - plane))| / count: 1 for a perfect plane
};

// Finds the plane by FFT peak search, then refines it on the samples.
PhasePlane fit_phase_plane(const std::vector<PhaseSample>& samples);

// The starting lens estimate from the planes of all positions.
LensEstimate coarse_start(const display::Calibration& nominal, const std::vector<PositionData>& positions,
                          bool fit_view_cone, std::vector<PhasePlane>* planes = nullptr);

}  // namespace lfd::calib
