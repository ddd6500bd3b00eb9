#include "calib/phasors/block_phasors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

namespace lfd::calib {

double BlockPhasors::phase(int bx, int by) const {
  const double two_pi = 2.0 * std::numbers::pi;
  double t = std::atan2(im.at<float>(by, bx), re.at<float>(by, bx)) / two_pi;
  const int K = int(level.size());
  if (K >= 6) {
    // Levels y_k = a + c cos(2 pi k/K) + s sin(2 pi k/K), t = atan2(s, c) / 2 pi.
    Eigen::MatrixXd design(K, 3);
    Eigen::VectorXd y(K);
    for (int k = 0; k < K; ++k) {
      design.row(k) << 1.0, std::cos(two_pi * k / K), std::sin(two_pi * k / K);
      y[k] = level[size_t(k)].at<float>(by, bx);
    }
    std::vector<bool> kept(size_t(K), true);
    Eigen::Vector3d fit = design.colPivHouseholderQr().solve(y);
    for (int dropped = 0; dropped < 3; ++dropped) {
      const Eigen::VectorXd residual = y - design * fit;
      std::vector<double> magnitudes;
      int worst = -1;
      for (int k = 0; k < K; ++k) {
        if (!kept[size_t(k)]) continue;
        magnitudes.push_back(std::abs(residual[k]));
        if (worst < 0 || std::abs(residual[k]) > std::abs(residual[worst])) worst = k;
      }
      std::nth_element(magnitudes.begin(), magnitudes.begin() + magnitudes.size() / 2,
                       magnitudes.end());
      const double median = magnitudes[magnitudes.size() / 2];
      const double b = std::hypot(fit[1], fit[2]);
      if (!(std::abs(residual[worst]) > 3 * median && std::abs(residual[worst]) > 0.125 * b)) break;
      kept[size_t(worst)] = false;
      Eigen::MatrixXd a_kept(K - dropped - 1, 3);
      Eigen::VectorXd y_kept(K - dropped - 1);
      for (int k = 0, row = 0; k < K; ++k)
        if (kept[size_t(k)]) {
          a_kept.row(row) = design.row(k);
          y_kept[row++] = y[k];
        }
      fit = a_kept.colPivHouseholderQr().solve(y_kept);
      t = std::atan2(fit[2], fit[1]) / two_pi;
    }
  }
  return t - std::floor(t);
}

double BlockPhasors::modulation(int bx, int by, int steps) const {
  // |z| = (K/2) * 3 b (three channels summed) and a is the per-channel mean.
  const double z = std::hypot(re.at<float>(by, bx), im.at<float>(by, bx));
  return z / (1.5 * steps) / std::max(double(mean.at<float>(by, bx)), 1e-6);
}

BlockPhasors block_phasors(const std::vector<cv::Mat>& captures, int block_px) {
  const int K = int(captures.size());
  const cv::Size size = captures.at(0).size();
  const double two_pi = 2.0 * std::numbers::pi;
  BlockPhasors out;
  out.block_px = std::max(1, block_px);
  const int b = out.block_px;
  out.blocks = cv::Size(size.width / b, size.height / b);

  cv::Mat re(size, CV_32F, 0.0f), im(size, CV_32F, 0.0f), mean(size, CV_32F, 0.0f),
      clipped(size, CV_32F, 0.0f);
  std::vector<cv::Mat> level(static_cast<size_t>(K));
  for (int k = 0; k < K; ++k) {
    const float ck = float(std::cos(two_pi * k / K)), sk = float(std::sin(two_pi * k / K));
    level[size_t(k)] = cv::Mat(size, CV_32F);
    const cv::Mat& img = captures[size_t(k)];
#pragma omp parallel for schedule(static)
    for (int y = 0; y < size.height; ++y) {
      const cv::Vec3f* row = img.ptr<cv::Vec3f>(y);
      float* r = re.ptr<float>(y);
      float* i = im.ptr<float>(y);
      float* m = mean.ptr<float>(y);
      float* c = clipped.ptr<float>(y);
      float* l = level[size_t(k)].ptr<float>(y);
      for (int x = 0; x < size.width; ++x) {
        const float s = row[x][0] + row[x][1] + row[x][2];
        r[x] += s * ck;
        i[x] += s * sk;
        m[x] += s / (3.0f * K);
        l[x] = s / 3.0f;
        if (std::max({row[x][0], row[x][1], row[x][2]}) >= 0.985f) c[x] = 1.0f;
      }
    }
  }
  auto shrink = [&](const cv::Mat& m) {
    cv::Mat o;
    cv::resize(m(cv::Rect(0, 0, out.blocks.width * b, out.blocks.height * b)), o, out.blocks, 0,
               0, cv::INTER_AREA);
    return o;
  };
  const cv::Mat valid = 1.0f - clipped;
  out.valid = shrink(valid);
  // Block means over the valid pixels only.
  auto masked = [&](const cv::Mat& m) {
    cv::Mat o;
    cv::multiply(m, valid, o);
    o = shrink(o);
    cv::divide(o, cv::max(out.valid, 1e-6f), o);
    return o;
  };
  out.re = masked(re);
  out.im = masked(im);
  out.mean = masked(mean);
  for (const auto& l : level) out.level.push_back(masked(l));
  return out;
}

}  // namespace lfd::calib
