#pragma once
// Dense registration from the fringe patterns (sim/patterns.hpp): 4 phase-shifted sinusoids
// along the panel's x and y axes, shown alike in every view. Per block of camera pixels the
// phasor sum_k I_k exp(2 pi i k / 4) has the argument 2 pi x / period, so the block sees the
// content at panel column x (and row y) modulo the period; the board registration, a few
// pixels accurate, picks the period. The result is thousands of correspondences spread over
// the whole screen (the board gives ~40), which is what pins down the camera's perspective,
// and so its lateral position (the center) and the panel mapping (pitch, view cone).
#include <vector>

#include <opencv2/core.hpp>

#include "sim/patterns.hpp"
#include "calib/registration/registration.hpp"

namespace lfd::calib {

struct FringeCorrespondences {
  std::vector<cv::Point2f> image_px;  // block centres (distorted camera pixels)
  std::vector<cv::Point2d> panel_px;  // content seen there (OpenCV panel pixel coordinates)
};

struct FringeDecodeOptions {
  int block_px = 12;             // camera pixels per block side: several lenses per block
  double min_modulation = 0.15;  // b / a
  double panel_margin = 0.02;    // of the panel size, skipped along the edges
  bool correct_exposure_drift = true;  // as in PhaseDecodeOptions (calib/phasors/exposure_drift.hpp)
  bool exposure_row_gain = true;       // as in PhaseDecodeOptions
};

// `x_captures[k]` / `y_captures[k]`: the captures of fringe step k (CV_32FC3 RGB in [0, 1]).
// `board` is the board registration (unwraps the fringe order, outlines the screen).
FringeCorrespondences decode_fringes(const std::vector<cv::Mat>& x_captures,
                                     const std::vector<cv::Mat>& y_captures,
                                     const Registration& board, const sim::PatternSet& set,
                                     const FringeDecodeOptions& options = {});

}  // namespace lfd::calib
