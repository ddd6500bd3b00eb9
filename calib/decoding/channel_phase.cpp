#include "calib/decoding/channel_phase.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace lfd::calib {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double wrap_half(double x) { return x - std::floor(x + 0.5); }

}  // namespace

ChannelPhasors::ChannelPhasors(const std::vector<cv::Mat>& captures, int block_px,
                               const ExposureDrift& drift) {
  const int K = int(captures.size());
  const int b = std::max(1, block_px);
  const cv::Size size = captures.at(0).size();
  const cv::Size blocks(size.width / b, size.height / b);
  const cv::Rect used(0, 0, blocks.width * b, blocks.height * b);
  for (int c = 0; c < 3; ++c) {
    re_[c] = cv::Mat(blocks, CV_32F, 0.0f);
    im_[c] = cv::Mat(blocks, CV_32F, 0.0f);
  }
  for (int k = 0; k < K; ++k) {
    cv::Mat level;  // block means per channel
    cv::resize(captures[size_t(k)](used), level, blocks, 0, 0, cv::INTER_AREA);
    // The drift is gain (per row) and offset per photo (exposure_drift.hpp): undone per
    // channel alike.
    if (size_t(k) < drift.photos.size()) level = divide_exposure(level, drift.photos[size_t(k)]);
    std::array<cv::Mat, 3> channel;
    cv::split(level, channel.data());
    for (int c = 0; c < 3; ++c) {
      re_[c] += channel[c] * float(std::cos(kTwoPi * k / K));
      im_[c] += channel[c] * float(std::sin(kTwoPi * k / K));
    }
  }
}

ChannelPhase ChannelPhasors::at(int bx, int by, double psi) const {
  ChannelPhase out;
  double total = 0;
  std::array<double, 3> magnitude{};
  for (int c = 0; c < 3; ++c) {
    const std::complex<double> z(re_[c].at<float>(by, bx), im_[c].at<float>(by, bx));
    magnitude[c] = std::abs(z);
    total += magnitude[c];
    out.offset_periods[c] = float(wrap_half(std::arg(z) / kTwoPi - psi));
  }
  for (int c = 0; c < 3; ++c) out.weight[c] = float(total > 0 ? magnitude[c] / total : 1.0 / 3);
  return out;
}

double reweighted_phase(double psi, const ChannelPhase& ch,
                        const std::array<double, 3>& shift_periods) {
  std::complex<double> sum(0, 0);
  for (int c = 0; c < 3; ++c)
    sum += double(ch.weight[c]) *
           std::polar(1.0, kTwoPi * (double(ch.offset_periods[c]) - shift_periods[c]));
  const double t = psi + std::arg(sum) / kTwoPi;
  return t - std::floor(t);
}

}  // namespace lfd::calib
