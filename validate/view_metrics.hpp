#pragma once
// Crosstalk and view separation from angular profiles (docs/validation.md "View separation"),
// black level subtracted, evaluated at each view's luminance peak theta_i*:
//   X_i = sum_{j != i} (L_j - L_K) / (L_i - L_K)          (system crosstalk of view i)
//   X_i^adj: the same over the two neighbours i - 1, i + 1 (wrapping: the cone repeats)
//   V_i = (L_i - L_K) / sum_j (L_j - L_K)                  (view separation, 1 = pure)
#include <vector>

#include "validate/view_profiles.hpp"

namespace lfd::validate {

struct ViewMetrics {
  int view = 0;
  double peak_theta_deg = 0;
  double peak_luminance = 0;      // L_i(theta_i*) - L_K(theta_i*)
  double crosstalk = 0;           // X_i
  double adjacent_crosstalk = 0;  // X_i^adj
  double separation = 0;          // V_i
};

struct ViewSummary {
  std::vector<ViewMetrics> per_view;
  double mean_crosstalk = 0;
  double mean_adjacent_crosstalk = 0;
  double mean_separation = 0;
  double min_separation = 0;
};

ViewSummary summarise(const ViewProfiles& profiles);

}  // namespace lfd::validate
