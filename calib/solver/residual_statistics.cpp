#include "calib/solver/residual_statistics.hpp"

#include <algorithm>
#include <cmath>

namespace lfd::calib {

namespace {

double median_in_place(std::vector<double>& x) {
  const auto mid = x.begin() + std::ptrdiff_t(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

}  // namespace

RobustResiduals robust_residuals(std::vector<double> residuals) {
  RobustResiduals out;
  out.stats.count = long(residuals.size());
  if (residuals.empty()) {
    out.stats.rms_periods = 1;
    out.stats.inlier_fraction = 0;
    return out;
  }
  std::vector<double> dev = residuals;
  const double median = median_in_place(dev);
  for (double& d : dev) d = std::abs(d - median);
  // 1.4826 = 1 / Phi^-1(3/4): MAD to standard deviation for Gaussian residuals.
  out.robust_sigma_periods = 1.4826 * median_in_place(dev);
  out.cut_periods = kOutlierCutSigmas * out.robust_sigma_periods;
  std::vector<double> abs_r(residuals.size());
  std::transform(residuals.begin(), residuals.end(), abs_r.begin(),
                 [](double r) { return std::abs(r); });
  out.stats.median_abs_periods = median_in_place(abs_r);
  double sum2 = 0;
  long inliers = 0;
  for (double r : residuals)
    if (std::abs(r - median) <= out.cut_periods) {
      sum2 += r * r;
      ++inliers;
    }
  out.stats.inlier_fraction = double(inliers) / double(residuals.size());
  out.stats.rms_periods = inliers ? std::sqrt(sum2 / double(inliers)) : 1.0;
  return out;
}

}  // namespace lfd::calib
