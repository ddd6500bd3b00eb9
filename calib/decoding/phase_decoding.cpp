#include "calib/decoding/phase_decoding.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "calib/phasors/block_phasors.hpp"

namespace lfd::calib {

DecodedPhase decode_phase(const std::vector<cv::Mat>& captures, const Registration& registration,
                          const sim::PatternSet& set, const PhaseDecodeOptions& options) {
  const int K = int(captures.size());
  const double two_pi = 2.0 * std::numbers::pi;
  BlockPhasors bp = block_phasors(captures, options.block_px);
  ExposureDrift drift;
  if (options.correct_exposure_drift) {
    ExposureDriftOptions drift_options;
    if (!options.exposure_row_gain) drift_options.row_segments = 0;
    drift = estimate_exposure_drift(bp, drift_options);
    remove_exposure_drift(bp, drift);
  }
  const ChannelPhasors channel_phasors(captures, options.block_px, drift);
  const cv::Size blocks = bp.blocks;
  std::vector<cv::Point2f> centres;
  for (int by = 0; by < blocks.height; ++by)
    for (int bx = 0; bx < blocks.width; ++bx) centres.push_back(bp.centre_px(bx, by));
  const std::vector<display::ScreenUV> uv = registration.image_to_panel_uv(centres);

  DecodedPhase out;
  out.exposure = drift;
  out.step_correlation.assign(size_t(K), 0.0);
  std::vector<double> corr_num(size_t(K), 0), corr_a(size_t(K), 0), corr_b(size_t(K), 0);
  std::vector<float> modulations;
  const double m = options.panel_margin;
  const double marker_margin = set.markers.quiet_px;
  for (int by = 0; by < blocks.height; ++by)
    for (int bx = 0; bx < blocks.width; ++bx) {
      const display::ScreenUV p = uv[size_t(by) * blocks.width + bx];
      if (!(p.u > m && p.u < 1 - m && p.v > m && p.v < 1 - m)) continue;
      if (set.under_marker(p.u, p.v, marker_margin)) continue;
      ++out.blocks_on_panel;
      if (bp.valid.at<float>(by, bx) < 0.5) {  // a block keeps its phase if half is valid
        ++out.blocks_clipped;
        continue;
      }
      const double modulation = bp.modulation(bx, by, K);
      if (!(modulation >= options.min_modulation)) {
        ++out.blocks_low_modulation;
        continue;
      }
      const double psi = bp.phase(bx, by);
      const double a = bp.mean.at<float>(by, bx);
      out.samples.push_back({float(p.u), float(p.v), float(psi), float(modulation)});
      out.channels.push_back(channel_phasors.at(bx, by, psi));
      modulations.push_back(float(modulation));
      for (int k = 0; k < K; ++k) {
        const double e = bp.level[size_t(k)].at<float>(by, bx) - a;
        const double model = std::cos(two_pi * (psi - double(k) / K));
        corr_num[size_t(k)] += e * model;
        corr_a[size_t(k)] += e * e;
        corr_b[size_t(k)] += model * model;
      }
    }
  for (int k = 0; k < K; ++k)
    out.step_correlation[size_t(k)] =
        corr_num[size_t(k)] / std::sqrt(std::max(1e-30, corr_a[size_t(k)] * corr_b[size_t(k)]));
  if (!modulations.empty()) {
    std::nth_element(modulations.begin(), modulations.begin() + modulations.size() / 2,
                     modulations.end());
    out.median_modulation = modulations[modulations.size() / 2];
  }
  return out;
}

}  // namespace lfd::calib
