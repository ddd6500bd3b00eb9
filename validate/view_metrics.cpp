#include "validate/view_metrics.hpp"

#include <algorithm>
#include <limits>

namespace lfd::validate {

ViewSummary summarise(const ViewProfiles& p) {
  ViewSummary s;
  const int n = p.views;
  for (int i = 0; i < n; ++i) {
    // theta_i* = argmax L_i(theta) (docs/validation.md "View separation").
    const auto& li = p.view[i];
    const size_t k = size_t(std::max_element(li.begin(), li.end()) - li.begin());
    ViewMetrics m;
    m.view = i;
    m.peak_theta_deg = p.theta_deg[k];
    const double black = p.black[k];
    m.peak_luminance = li[k] - black;
    double others = 0, total = 0;
    for (int j = 0; j < n; ++j) {
      const double lj = p.view[j][k] - black;
      total += lj;
      if (j != i) others += lj;
    }
    const double adjacent = (p.view[(i + n - 1) % n][k] - black) +
                            (n > 2 ? p.view[(i + 1) % n][k] - black : 0.0);
    const double inf = std::numeric_limits<double>::infinity();
    m.crosstalk = m.peak_luminance > 0 ? others / m.peak_luminance : inf;
    m.adjacent_crosstalk = m.peak_luminance > 0 ? adjacent / m.peak_luminance : inf;
    m.separation = total > 0 ? m.peak_luminance / total : 0.0;
    s.per_view.push_back(m);
  }
  if (n > 0) {
    s.min_separation = 1.0;
    for (const auto& m : s.per_view) {
      s.mean_crosstalk += m.crosstalk / n;
      s.mean_adjacent_crosstalk += m.adjacent_crosstalk / n;
      s.mean_separation += m.separation / n;
      s.min_separation = std::min(s.min_separation, m.separation);
    }
  }
  return s;
}

}  // namespace lfd::validate
