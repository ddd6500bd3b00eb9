#pragma once
// What one subpixel contributes to the light a lens sends toward a camera (docs/validation.md "The
// forward model"): the subpixel is a box one subpixel wide (1/(3W) in u) along its pixel row, and
// the lens blurs it with its point spread, a Gaussian of sigma_A lens periods in phase, which is
// sigma_A / pitch' in u. The weight of a box centred at distance d from the seen point Q is
//   k(d) = Phi((d + w/2) / sigma_u) - Phi((d - w/2) / sigma_u),
// tabulated once per sigma because the simulator evaluates it tens of millions of times.
#include <cmath>
#include <vector>

namespace lfd::display {

class PhaseKernel {
 public:
  // box_width_u: subpixel width in u (1/(3W)); sigma_u: lens point spread in u (may be 0).
  PhaseKernel(double box_width_u, double sigma_u);

  double sigma_u() const { return sigma_u_; }
  // Beyond this distance (in u) a box contributes less than 1e-7.
  double reach_u() const { return reach_u_; }
  // Weight of a box centred at distance d_u (in u) from the seen point; in [0, 1].
  double operator()(double d_u) const {
    const double t = std::abs(d_u) * scale_;
    const auto i = static_cast<size_t>(t);
    if (i + 1 >= table_.size()) return 0.0;
    const double a = t - double(i);
    return table_[i] + a * (table_[i + 1] - table_[i]);
  }

 private:
  double sigma_u_ = 0;
  double reach_u_ = 0;
  double scale_ = 0;           // table samples per unit u
  std::vector<double> table_;  // k(d) at d = i / scale_
};

}  // namespace lfd::display
