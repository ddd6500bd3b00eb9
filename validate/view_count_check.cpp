#include "validate/view_count_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "display/lens_relations.hpp"
#include "display/view_count.hpp"
#include "util/error.hpp"
#include "validate/view_metrics.hpp"

namespace lfd::validate {

double parallax_blur(const ViewProfiles& p, double view_cone_deg) {
  double sum = 0;
  int count = 0;
  for (size_t a = 0; a < p.theta_deg.size(); ++a) {
    // The eye's view position relative to the centre view, -1/2 .. 1/2 across the cone (the
    // profiles' eyes are level with each panel point: no vertical term).
    const double s_eye = display::seen_fraction_of_tan(
                             std::tan(p.theta_deg[a] * std::numbers::pi / 180.0), 0.0, 0.0,
                             view_cone_deg) - 0.5;
    if (std::abs(s_eye) >= 0.4) continue;
    double total = 0, moment = 0;
    for (int j = 0; j < p.views; ++j) {
      const double w = std::max(0.0, p.view[j][a] - p.black[a]);
      const double s_j = (j + 0.5) / p.views - 0.5;
      total += w;
      moment += w * (s_j - s_eye) * (s_j - s_eye);
    }
    if (total <= 0) continue;
    sum += std::sqrt(moment / total);
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

ViewCountSweep sweep_view_counts(const display::Calibration& truth, const std::vector<int>& counts,
                                 ProfileOptions options, Progress* progress) {
  if (counts.empty()) throw_input_error("views sweep: no view counts given");
  if (!std::is_sorted(counts.begin(), counts.end()))
    throw_input_error("views sweep: view counts must ascend");
  ViewCountSweep sweep;
  sweep.recommended = display::recommend_view_count(truth).views;
  for (int views : counts) {
    options.views = views;
    const ViewProfiles profiles = measure_view_profiles(truth, truth, options, progress);
    const ViewSummary summary = summarise(profiles);
    sweep.points.push_back({views, parallax_blur(profiles, truth.display.view_cone_deg),
                            summary.mean_separation, summary.mean_adjacent_crosstalk});
  }
  sweep.blur_floor = sweep.points.back().parallax_blur;
  sweep.saturation = sweep.points.back().views;
  for (const auto& p : sweep.points)
    if (p.parallax_blur <= 1.1 * sweep.blur_floor) {
      sweep.saturation = p.views;
      break;
    }
  return sweep;
}

}  // namespace lfd::validate
