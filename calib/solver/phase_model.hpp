#pragma once
// The phase model the lens solve fits (docs/calibration.md, 3.4) and its two cost functions
// with hand-written derivatives: PhaseResidual (the data term: Jets for the lens, camera and
// cover, the correction field's basis weights written out) and LinearCombination (the
// smoothness prior and the gauge). A header so that their gradient check
// (tests/calib/cost_gradients_test.cpp) tests the very classes the solve builds; only
// lens_solver.cpp and that test include it.
#include <cmath>
#include <utility>
#include <vector>

#include <ceres/ceres.h>

#include "display/correction_field.hpp"
#include "display/display_calibration.hpp"
#include "display/lens_relations.hpp"

namespace lfd::calib::phase_model {

template <typename T>
T wrap_half(const T& x) {  // to [-0.5, 0.5): the residual of a phase known modulo 1
  return x - T(std::floor(display::scalar_part(x) + 0.5));
}

// The display constants the phase model needs besides the unknowns.
struct DisplayConstants {
  display::ScreenGeometry geometry;
  double width_m, height_m;
  double sign;  // s = +1 with invView, -1 without (docs/calibration.md section 3.2)
  bool vertical_parallax;  // false: the model of horizontal offsets only (for comparison)
  // The nominal's cover: registration used its thickness; the solve may move it (by `dt`,
  // SolverOptions::cover_sigma_m; docs/calibration.md, "The cover layer").
  display::CoverLayer cover;
  static DisplayConstants of(const display::DisplayCalibration& d, bool vertical_parallax) {
    return {d.geometry(), d.width_m(), d.height_m(), d.inv_view ? 1.0 : -1.0, vertical_parallax,
            d.cover};
  }
  // Px, Py of a panel point at screen (u, v), display frame (metres, origin at the screen
  // centre, y up as v).
  template <typename T>
  T panel_x_m(const T& u) const { return (u - 0.5) * width_m; }
  template <typename T>
  T panel_y_m(const T& v) const { return (v - 0.5) * height_m; }
  // f_seen at physical point (u, v) for a camera {Cx, Cy, Cz}, the lens' tilt and the cover's
  // thickness changed by dt from the nominal's.
  template <typename T>
  T seen(const T* cam, const T& u, const T& v, const T& tilt, const T& view_cone_deg,
         const T& dt) const {
    const T dx = cam[0] - panel_x_m(u);
    const T dy = vertical_parallax ? T(cam[1] - panel_y_m(v)) : T(0.0);
    const T d = display::cover_seen_distance(dx, dy, cam[2], T(cover.thickness_m) + dt,
                                             cover.refractive_index);
    return display::seen_fraction(dx, dy, d, display::line_tilt(geometry, tilt), view_cone_deg);
  }
};

struct Sample {
  double u, v, u_phys, a_nom, psi;
  // d(u, v) / d(cover thickness), per metre: where registration puts the sample's panel point
  // moves with the cover it assumed (PositionData::sample_per_cover).
  double du_dt = 0, dv_dt = 0;
  display::BSplineWeights wu, wv;
};

// psi model without the correction field: f_seen(P) + s (A_true_linear(X) - A_nom(X)).
// lens = {pitch_lpi, slope, center, view_cone_deg}, cam = {Cx, Cy, Cz}, dt the cover's change
// of thickness, which moves the sample's panel point (and its content point with it) along
// its gradient; `nominal_du`, `nominal_dv` the nominal phase's gradient.
template <typename T>
T psi_linear(const DisplayConstants& dc, const T* lens, const T* cam, const T& dt, const Sample& s,
             double nominal_du, double nominal_dv) {
  const display::ShaderTerms<T> terms = display::shader_terms(dc.geometry, lens[0], lens[1]);
  const T du = dt * s.du_dt, dv = dt * s.dv_dt;
  const T u = T(s.u) + du, v = T(s.v) + dv;
  const T a_true = (u + v * terms.tilt) * terms.pitch_periods - lens[2];
  const T a_nom = T(s.a_nom) + du * nominal_du + dv * nominal_dv;
  const T f_seen = dc.seen(cam, T(s.u_phys) + du, v, terms.tilt, lens[3], dt);
  return f_seen + T(dc.sign) * (a_true - a_nom);
}

// The data term. Parameter blocks: lens (4), camera (3), the cover's change of thickness (1),
// then the 16 control points whose B-spline basis covers the sample (one block each, so the
// Jacobian stays sparse). The
// correction field enters linearly, r = wrap(psi_obs - psi_lin - s w) / sigma, so its
// derivatives are the basis weights; the rest is differentiated with Jets.
class PhaseResidual : public ceres::CostFunction {
 public:
  PhaseResidual(const DisplayConstants& dc, const Sample& s, double inv_sigma, bool with_field,
                double nominal_du, double nominal_dv)
      : dc_(dc), s_(s), inv_sigma_(inv_sigma), with_field_(with_field), nominal_du_(nominal_du),
        nominal_dv_(nominal_dv) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(4);
    mutable_parameter_block_sizes()->push_back(3);
    mutable_parameter_block_sizes()->push_back(1);
    if (with_field_)
      for (int i = 0; i < 16; ++i) mutable_parameter_block_sizes()->push_back(1);
  }

  bool Evaluate(double const* const* p, double* residual, double** jacobians) const override {
    using Jet = ceres::Jet<double, 8>;
    Jet lens[4], cam[3];
    for (int i = 0; i < 4; ++i) lens[i] = Jet(p[0][i], i);
    for (int i = 0; i < 3; ++i) cam[i] = Jet(p[1][i], 4 + i);
    const Jet dt(p[2][0], 7);
    double w = 0;
    if (with_field_)
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) w += p[3 + 4 * b + a][0] * (s_.wu.w[a] * s_.wv.w[b]);
    const Jet model = psi_linear(dc_, lens, cam, dt, s_, nominal_du_, nominal_dv_) + dc_.sign * w;
    const Jet r = wrap_half(Jet(s_.psi) - model) * inv_sigma_;
    residual[0] = r.a;
    if (jacobians) {
      if (jacobians[0])
        for (int i = 0; i < 4; ++i) jacobians[0][i] = r.v[i];
      if (jacobians[1])
        for (int i = 0; i < 3; ++i) jacobians[1][i] = r.v[4 + i];
      if (jacobians[2]) jacobians[2][0] = r.v[7];
      if (with_field_)
        for (int b = 0; b < 4; ++b)
          for (int a = 0; a < 4; ++a)
            if (jacobians[3 + 4 * b + a])
              jacobians[3 + 4 * b + a][0] = -dc_.sign * s_.wu.w[a] * s_.wv.w[b] * inv_sigma_;
    }
    return true;
  }

 private:
  DisplayConstants dc_;
  Sample s_;
  double inv_sigma_;
  bool with_field_;
  double nominal_du_, nominal_dv_;
};

// r = sum_j a_j x_j over scalar blocks: the smoothness prior and the gauge constraints.
class LinearCombination : public ceres::CostFunction {
 public:
  explicit LinearCombination(std::vector<double> a) : a_(std::move(a)) {
    set_num_residuals(1);
    for (size_t i = 0; i < a_.size(); ++i) mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* p, double* residual, double** jacobians) const override {
    residual[0] = 0;
    for (size_t i = 0; i < a_.size(); ++i) residual[0] += a_[i] * p[i][0];
    if (jacobians)
      for (size_t i = 0; i < a_.size(); ++i)
        if (jacobians[i]) jacobians[i][0] = a_[i];
    return true;
  }

 private:
  std::vector<double> a_;
};

}  // namespace lfd::calib::phase_model
