#include "calib/registration/fringe_registration.hpp"

#include <cmath>

#include "calib/phasors/block_phasors.hpp"
#include "calib/phasors/exposure_drift.hpp"

namespace lfd::calib {

FringeCorrespondences decode_fringes(const std::vector<cv::Mat>& x_captures,
                                     const std::vector<cv::Mat>& y_captures,
                                     const Registration& board, const sim::PatternSet& set,
                                     const FringeDecodeOptions& options) {
  FringeCorrespondences out;
  if (x_captures.size() < 3 || y_captures.size() != x_captures.size()) return out;
  BlockPhasors bx = block_phasors(x_captures, options.block_px);
  BlockPhasors by = block_phasors(y_captures, options.block_px);
  if (options.correct_exposure_drift) {
    ExposureDriftOptions drift_options;
    if (!options.exposure_row_gain) drift_options.row_segments = 0;
    remove_exposure_drift(bx, estimate_exposure_drift(bx, drift_options));
    remove_exposure_drift(by, estimate_exposure_drift(by, drift_options));
  }
  const int steps = int(x_captures.size());
  const auto& d = set.nominal.display;
  const double period = set.fringe_period_px;

  std::vector<cv::Point2f> centres;
  for (int j = 0; j < bx.blocks.height; ++j)
    for (int i = 0; i < bx.blocks.width; ++i) centres.push_back(bx.centre_px(i, j));
  const std::vector<display::ScreenUV> predicted = board.image_to_panel_uv(centres);

  const double m = options.panel_margin;
  for (int j = 0; j < bx.blocks.height; ++j)
    for (int i = 0; i < bx.blocks.width; ++i) {
      const size_t n = size_t(j) * bx.blocks.width + i;
      const display::ScreenUV p = predicted[n];
      if (!(p.u > m && p.u < 1 - m && p.v > m && p.v < 1 - m)) continue;
      if (set.under_marker(p.u, p.v, set.markers.quiet_px)) continue;
      if (bx.valid.at<float>(j, i) < 0.9 || by.valid.at<float>(j, i) < 0.9) continue;
      if (!(bx.modulation(i, j, steps) >= options.min_modulation &&
            by.modulation(i, j, steps) >= options.min_modulation))
        continue;
      // The board's prediction (OpenCV panel pixels) picks the fringe order.
      const double x_pred = p.u * d.screen_w - 0.5, y_pred = (1.0 - p.v) * d.screen_h - 0.5;
      auto unwrap = [&](double predicted_px, double phase) {
        const double order = std::round(predicted_px / period - phase);
        return (order + phase) * period;
      };
      const double x = unwrap(x_pred, bx.phase(i, j)), y = unwrap(y_pred, by.phase(i, j));
      // A fringe order off by one (a wrong prediction) is far beyond any registration error.
      if (std::abs(x - x_pred) > 0.3 * period || std::abs(y - y_pred) > 0.3 * period) continue;
      out.image_px.push_back(centres[n]);
      out.panel_px.emplace_back(x, y);
    }
  return out;
}

}  // namespace lfd::calib
