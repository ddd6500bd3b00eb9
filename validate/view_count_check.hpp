#pragma once
// Checks the view-count rule (display/view_count.hpp) with the simulator: how much parallax blur
// a viewer sees as the number of views grows. A viewer at direction theta should see the view
// rendered for theta, i.e. the camera offset s(theta) = tan(theta) / (2 tan(cone / 2)); what
// reaches the eye is a mixture of views j (camera offsets s_j = (j + 0.5)/V - 0.5) with weights
// w_j(theta) = (L_j - L_K) / sum (L - L_K) from the angular profiles. Its RMS spread around
// s(theta),
//     blur(theta) = sqrt( sum_j w_j(theta) (s_j - s(theta))^2 ),
// times a scene's disparity across the cone (pixels) is the width of the double image a point
// at that depth shows. It falls like 1/V while the views are wider than the optics resolves,
// then levels off at the lens blur: beyond that, more views cost rendering time and buy nothing.
#include <vector>

#include "display/calibration_file.hpp"
#include "validate/view_profiles.hpp"

namespace lfd::validate {

struct ViewCountPoint {
  int views = 0;
  double parallax_blur = 0;       // mean RMS spread in cone fractions (see above)
  double mean_separation = 0;     // mean V_i
  double mean_adjacent_crosstalk = 0;
};

// Mean parallax blur over the directions of a profile whose |s(theta)| < 0.4 (away from the
// cone edges, where the neighbouring lens repeats the views).
double parallax_blur(const ViewProfiles& profiles, double view_cone_deg);

struct ViewCountSweep {
  std::vector<ViewCountPoint> points;
  int recommended = 0;      // the rule's count (display::recommend_view_count)
  int saturation = 0;       // smallest swept count within 10 % of the largest count's blur
  double blur_floor = 0;    // blur at the largest swept count
};

// Measures every count in `counts` (ascending) for `truth` (interlaced with itself).
ViewCountSweep sweep_view_counts(const display::Calibration& truth, const std::vector<int>& counts,
                                 ProfileOptions options, Progress* progress = nullptr);

}  // namespace lfd::validate
