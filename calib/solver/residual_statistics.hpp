#pragma once
// Residual statistics that a bad fit cannot hide from: the scale is measured robustly over
// ALL samples (1.4826 x the median absolute deviation, the standard deviation for Gaussian
// residuals), and the RMS and the inliers are taken within a cut of a few of those scales.
// A fixed band (|r| < 0.15 period) would not do: a fit whose residuals spread over the band
// still reports an RMS below the band's own 0.087, so a residual gate on it cannot fail.
#include <vector>

#include "display/calibration_file.hpp"

namespace lfd::calib {

// The outlier cut in robust scales: 4 keeps 99.994 % of Gaussian residuals.
inline constexpr double kOutlierCutSigmas = 4.0;

struct RobustResiduals {
  display::ResidualStats stats;              // rms and inlier fraction within the cut; count: all samples
  double robust_sigma_periods = 0;  // 1.4826 MAD over all samples
  double cut_periods = 0;           // kOutlierCutSigmas robust sigmas around the median
};

// Of wrapped phase residuals (lens periods). Empty input: count 0, rms 1 (no fit).
RobustResiduals robust_residuals(std::vector<double> residuals);

}  // namespace lfd::calib
