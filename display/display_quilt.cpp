#include "display/display_quilt.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "display/view_count.hpp"
#include "util/error.hpp"

namespace lfd::display {

QuiltGrid quilt_grid_for_views(int views, double view_aspect) {
  if (views < 1 || views > 256)
    throw_input_error("views: {} is outside 1..256", views);
  if (!(view_aspect > 0) || !std::isfinite(view_aspect))
    throw_input_error("view aspect: {} must be a positive number", view_aspect);
  QuiltGrid best;
  int best_empty = std::numeric_limits<int>::max();
  double best_squareness = std::numeric_limits<double>::max();
  for (int cols = 1; cols <= views; ++cols) {
    const int rows = (views + cols - 1) / cols;
    const int empty = cols * rows - views;
    // |log(texture aspect)|: 0 for a square quilt texture.
    const double squareness = std::abs(std::log(cols * view_aspect / rows));
    if (empty < best_empty || (empty == best_empty && squareness < best_squareness - 1e-12)) {
      best = {cols, rows};
      best_empty = empty;
      best_squareness = squareness;
    }
  }
  return best;
}

double effective_view_cone_deg(const Calibration& calibration) {
  return calibration.view_cone_measured_deg.value_or(calibration.display.view_cone_deg);
}

DisplayQuilt quilt_for_display(const Calibration& calibration, std::optional<int> views) {
  DisplayQuilt q;
  q.view_aspect = double(calibration.display.screen_w) / calibration.display.screen_h;
  q.view_cone_deg = effective_view_cone_deg(calibration);
  q.cone_measured = calibration.view_cone_measured_deg.has_value();
  if (views) {
    q.views = *views;
    q.views_source = "--views";
  } else if (calibration.recommended_views) {
    q.views = *calibration.recommended_views;
    q.views_source = "recommended by the calibration";
  } else {
    q.views = recommend_view_count(calibration).views;
    q.views_source = "view-count rule";
  }
  q.grid = quilt_grid_for_views(q.views, q.view_aspect);
  return q;
}

std::string DisplayQuilt::describe() const {
  return fmt::format("{} views ({}) in {}x{} tiles of aspect {:.4g}, view cone {:.2f} deg ({})",
                     views, views_source, grid.cols, grid.rows, view_aspect, view_cone_deg,
                     cone_measured ? "measured" : "nominal");
}

ViewSize view_size_for_display(const DisplayQuilt& quilt, int height_px) {
  return {std::max(1, int(std::lround(height_px * quilt.view_aspect))), height_px};
}

}  // namespace lfd::display
