#include "calib/phasors/exposure_drift.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "display/correction_field.hpp"

namespace lfd::calib {

namespace {

// The blocks fully valid (nothing saturated) whose levels stay within `max_spread` of their
// mean in every step; of the median block's mean for darker blocks, which an offset drift
// moves by more than their own level allows.
std::vector<cv::Point> unmodulated_blocks(const BlockPhasors& p, double max_spread) {
  std::vector<float> means;
  for (int by = 0; by < p.blocks.height; ++by)
    for (int bx = 0; bx < p.blocks.width; ++bx)
      if (p.valid.at<float>(by, bx) > 0.999f) means.push_back(p.mean.at<float>(by, bx));
  if (means.empty()) return {};
  std::nth_element(means.begin(), means.begin() + long(means.size() / 2), means.end());
  const float typical = means[means.size() / 2];
  std::vector<cv::Point> out;
  for (int by = 0; by < p.blocks.height; ++by)
    for (int bx = 0; bx < p.blocks.width; ++bx) {
      const float mean = p.mean.at<float>(by, bx);
      if (!(p.valid.at<float>(by, bx) > 0.999f && mean > 1e-4f)) continue;
      float spread = 0;
      for (const auto& level : p.level)
        spread = std::max(spread, std::abs(level.at<float>(by, bx) - mean));
      if (spread < max_spread * std::max(mean, typical)) out.emplace_back(bx, by);
    }
  return out;
}

// The gain's basis along the height: one constant (segments = 0), or the segments + 3
// uniform cubic B-splines over t in [0, 1], evaluated at t.
int basis_size(int segments) { return segments > 0 ? segments + 3 : 1; }

Eigen::RowVectorXd row_basis(double t, int segments) {
  Eigen::RowVectorXd out = Eigen::RowVectorXd::Zero(basis_size(segments));
  if (segments <= 0) {
    out(0) = 1;
    return out;
  }
  // The correction field's uniform cubic B-spline (segments + 3 control points).
  const display::BSplineWeights w = display::bspline_weights(segments + 3, t);
  for (int a = 0; a < 4; ++a) out(w.i0 + a) = w.w[a];
  return out;
}

double row_t(int block_row, int block_rows) { return (block_row + 0.5) / block_rows; }

// Whether every segment of the height holds enough references for its share of the spline.
bool rows_covered(const std::vector<cv::Point>& blocks, int block_rows, int segments,
                  int min_per_segment) {
  if (segments <= 0) return false;
  std::vector<int> count(size_t(segments), 0);
  for (const auto& b : blocks)
    ++count[size_t(std::min(segments - 1, int(row_t(b.y, block_rows) * segments)))];
  return std::ranges::all_of(count, [&](int c) { return c >= min_per_segment; });
}

// Least squares level_k(b) = g_k(row of b) ref(b) + o_k over the reference blocks, ref = the
// block's mean level, g_k a spline along the rows (or one constant); gain only (o_k = 0) when
// the references are all about as bright (no lever arm). All photos share the design matrix:
// one QR, K right-hand sides.
ExposureDrift fit_drift(const BlockPhasors& p, const std::vector<cv::Point>& blocks,
                        int segments) {
  ExposureDrift out;
  out.reference_blocks = int(blocks.size());
  out.row_segments = segments;
  double lo = 1e9, hi = -1e9, sum_r = 0, sum_rr = 0;
  for (const auto& b : blocks) {
    const double r = p.mean.at<float>(b);
    lo = std::min(lo, r), hi = std::max(hi, r), sum_r += r, sum_rr += r * r;
  }
  const double n = double(blocks.size());
  const double var_r = sum_rr / n - (sum_r / n) * (sum_r / n);
  out.offset_fitted = hi - lo > 0.3 * hi && var_r > 0;

  const int nb = basis_size(segments), K = int(p.level.size()), rows = p.blocks.height;
  const int cols = nb + (out.offset_fitted ? 1 : 0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(long(blocks.size()), cols);
  Eigen::MatrixXd L(long(blocks.size()), K);
  for (size_t i = 0; i < blocks.size(); ++i) {
    const cv::Point b = blocks[i];
    A.row(long(i)).head(nb) = row_basis(row_t(b.y, rows), segments) * double(p.mean.at<float>(b));
    if (out.offset_fitted) A(long(i), nb) = 1;
    for (int k = 0; k < K; ++k) L(long(i), k) = p.level[size_t(k)].at<float>(b);
  }
  const Eigen::MatrixXd X = A.colPivHouseholderQr().solve(L);

  Eigen::MatrixXd row_basis_at(rows, nb);
  for (int r = 0; r < rows; ++r) row_basis_at.row(r) = row_basis(row_t(r, rows), segments);
  for (int k = 0; k < K; ++k) {
    PhotoExposure e;
    const Eigen::VectorXd g = row_basis_at * X.col(k).head(nb);
    e.gain = g.mean();
    if (segments > 0) e.row_gain.assign(g.data(), g.data() + g.size());
    e.offset = out.offset_fitted ? X(nb, k) : 0.0;
    out.photos.push_back(std::move(e));
  }
  return out;
}

}  // namespace

double PhotoExposure::gain_at(int block_row) const {
  if (row_gain.empty()) return gain;
  return row_gain[size_t(std::clamp(block_row, 0, int(row_gain.size()) - 1))];
}

double ExposureDrift::max_gain_change() const {
  double m = 0;
  for (const auto& p : photos) {
    m = std::max(m, std::abs(p.gain - 1));
    for (double g : p.row_gain) m = std::max(m, std::abs(g - 1));
  }
  return m;
}

double ExposureDrift::max_row_variation() const {
  double m = 0;
  for (const auto& p : photos)
    if (!p.row_gain.empty()) {
      const auto [lo, hi] = std::ranges::minmax_element(p.row_gain);
      m = std::max(m, 0.5 * (*hi - *lo));
    }
  return m;
}

ExposureDrift estimate_exposure_drift(const BlockPhasors& phasors,
                                      const ExposureDriftOptions& options) {
  // The drift itself moves every level, so the first passes admit more, and each next one
  // chooses again on the levels corrected by the fit before it. The fit is always of the
  // levels as photographed.
  ExposureDrift fit;
  // At least 4 block rows per segment: the spline stays a smoothing, not an interpolation.
  const int segments = std::min(options.row_segments, phasors.blocks.height / 4);
  for (const double looser : {4.0, 2.0, 1.0}) {
    BlockPhasors corrected = phasors;
    if (!fit.photos.empty()) remove_exposure_drift(corrected, fit);
    const auto blocks = unmodulated_blocks(corrected, looser * options.max_reference_spread);
    if (int(blocks.size()) < options.min_reference_blocks) break;
    const bool covered = rows_covered(blocks, phasors.blocks.height, segments,
                                      options.min_references_per_segment);
    fit = fit_drift(phasors, blocks, covered ? segments : 0);
  }
  return fit;
}

cv::Mat divide_exposure(const cv::Mat& level, const PhotoExposure& e) {
  cv::Mat out(level.size(), level.type());
  for (int r = 0; r < level.rows; ++r) {
    const double g = e.gain_at(r);
    cv::Mat row = out.row(r);
    level.row(r).convertTo(row, level.type(), 1.0 / g, -e.offset / g);
  }
  return out;
}

void remove_exposure_drift(BlockPhasors& p, const ExposureDrift& drift) {
  const int K = int(p.level.size());
  if (drift.photos.size() != size_t(K)) return;
  const double two_pi = 2.0 * std::numbers::pi;
  cv::Mat re(p.blocks, CV_32F, 0.0f), im(p.blocks, CV_32F, 0.0f), mean(p.blocks, CV_32F, 0.0f);
  for (int k = 0; k < K; ++k) {
    // A new matrix, not in place: copies of a BlockPhasors share their levels' pixels.
    const cv::Mat level = divide_exposure(p.level[size_t(k)], drift.photos[size_t(k)]);
    p.level[size_t(k)] = level;
    // The sums block_phasors makes: three channels' z over the block's valid pixels.
    re += level * float(3.0 * std::cos(two_pi * k / K));
    im += level * float(3.0 * std::sin(two_pi * k / K));
    mean += level * float(1.0 / K);
  }
  p.re = re;
  p.im = im;
  p.mean = mean;
}

}  // namespace lfd::calib
