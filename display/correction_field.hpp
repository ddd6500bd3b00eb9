#pragma once
// The per-device correction field w(u, v) of the lens phase (docs/display-model.md "Phase and
// view"), in lens periods: a uniform cubic B-spline over the screen (u, v in [0, 1], v up) with nx
// x ny control points. Cubic B-splines are C2 and local, so a smoothness prior on the control
// points is a prior on the warp, and the solver touches 16 coefficients per observation.
#include <array>
#include <vector>

#include <nlohmann/json.hpp>

namespace lfd::display {

struct BSplineWeights {
  int i0 = 0;                   // first control point index
  std::array<double, 4> w{};    // weights of control points i0 .. i0 + 3
};

// Basis weights of a uniform cubic B-spline with n >= 4 control points at t in [0, 1].
BSplineWeights bspline_weights(int n, double t);

class CorrectionField {
 public:
  CorrectionField() = default;  // empty: w = 0 everywhere
  CorrectionField(int nx, int ny, std::vector<double> coefficients);
  static CorrectionField zeros(int nx, int ny);

  bool empty() const { return coefficients_.empty(); }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  const std::vector<double>& coefficients() const { return coefficients_; }
  std::vector<double>& coefficients() { return coefficients_; }

  double operator()(double u, double v) const;
  // Evaluates with externally held coefficients (the solver's parameter block); templated so
  // Ceres can differentiate through it.
  template <typename T>
  static T evaluate(const T* coefficients, int nx, int ny, double u, double v) {
    const BSplineWeights wu = bspline_weights(nx, u);
    const BSplineWeights wv = bspline_weights(ny, v);
    T sum = T(0);
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a)
        sum += coefficients[(wv.i0 + b) * nx + (wu.i0 + a)] * (wu.w[a] * wv.w[b]);
    return sum;
  }

  // Minimum and maximum over a dense grid of the screen, in lens periods.
  std::array<double, 2> range() const;

  nlohmann::ordered_json to_json() const;
  // Throws InputError("<where>: correction: ...") for a malformed or wrongly sized grid.
  static CorrectionField from_json(const nlohmann::ordered_json& j, const std::string& where);

 private:
  int nx_ = 0, ny_ = 0;
  std::vector<double> coefficients_;  // row-major, ny rows of nx (row 0 at v = 0)
};

// The field minus its least-squares plane a + b u + c v over the screen: the gauge the lens
// phase's linear terms absorb (the solver's gauge, docs/calibration.md).
CorrectionField remove_gauge(const CorrectionField& field);

}  // namespace lfd::display
