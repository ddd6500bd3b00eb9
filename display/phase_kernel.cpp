#include "display/phase_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lfd::display {

namespace {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

}  // namespace

PhaseKernel::PhaseKernel(double box_width_u, double sigma_u) : sigma_u_(std::max(0.0, sigma_u)) {
  if (!(box_width_u > 0) || !std::isfinite(sigma_u))
    throw std::invalid_argument("PhaseKernel: box width must be > 0 and sigma finite");
  const double half = 0.5 * box_width_u;
  // 5.5 sigma past the box edge the Gaussian tail is below 2e-8.
  reach_u_ = half + 5.5 * sigma_u_;
  // 512 samples per box width keep the linear interpolation error of a sharp edge (sigma -> 0)
  // to a 1/512 sliver of a subpixel; a blurred edge is smoother still.
  const double step = std::min(box_width_u / 512.0, sigma_u_ > 0 ? sigma_u_ / 16.0 : 1e300);
  scale_ = 1.0 / step;
  const size_t n = size_t(std::ceil(reach_u_ * scale_)) + 2;
  table_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double d = double(i) * step;
    if (sigma_u_ <= 0) {
      table_[i] = d < half ? 1.0 : (d == half ? 0.5 : 0.0);
    } else {
      table_[i] = normal_cdf((d + half) / sigma_u_) - normal_cdf((d - half) / sigma_u_);
    }
  }
  table_.back() = 0.0;
}

}  // namespace lfd::display
