#include "calib/phase_decoding.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace lfd::calib {

DecodedPhase decode_phase(const std::vector<cv::Mat>& captures, const Registration& registration,
                          const PatternSet& set, const PhaseDecodeOptions& options) {
  const int K = int(captures.size());
  const cv::Size size = captures.at(0).size();
  const int b = std::max(1, options.block_px);
  const cv::Size blocks(size.width / b, size.height / b);
  const double two_pi = 2.0 * std::numbers::pi;

  // Per pixel: channel-summed phasor, mean level, saturation flag, and the per-step levels.
  cv::Mat re(size, CV_32F, 0.0f), im(size, CV_32F, 0.0f), mean(size, CV_32F, 0.0f),
      clipped(size, CV_32F, 0.0f);
  // Saturated pixels (glare, specular reflections) carry no phase: they are left out of the
  // block sums below, and a block keeps its phase if at least half of its pixels are valid.
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
    cv::Mat out;
    cv::resize(m(cv::Rect(0, 0, blocks.width * b, blocks.height * b)), out, blocks, 0, 0,
               cv::INTER_AREA);
    return out;
  };
  cv::Mat valid = 1.0f - clipped;
  auto masked = [&](const cv::Mat& m) {
    cv::Mat out;
    cv::multiply(m, valid, out);
    return shrink(out);
  };
  const cv::Mat bvalid = shrink(valid);
  const cv::Mat bre = masked(re), bim = masked(im), bmean = masked(mean);
  std::vector<cv::Mat> blevel;
  for (const auto& l : level) blevel.push_back(masked(l));

  std::vector<cv::Point2f> centres;
  for (int by = 0; by < blocks.height; ++by)
    for (int bx = 0; bx < blocks.width; ++bx)
      centres.emplace_back(bx * b + 0.5f * b - 0.5f, by * b + 0.5f * b - 0.5f);
  const std::vector<ScreenUV> uv = registration.image_to_panel_uv(centres);

  DecodedPhase out;
  out.step_correlation.assign(size_t(K), 0.0);
  std::vector<double> corr_num(size_t(K), 0), corr_a(size_t(K), 0), corr_b(size_t(K), 0);
  std::vector<float> modulations;
  const double m = options.panel_margin;
  const double marker_margin = set.markers.quiet_px;
  for (int by = 0; by < blocks.height; ++by)
    for (int bx = 0; bx < blocks.width; ++bx) {
      const ScreenUV p = uv[size_t(by) * blocks.width + bx];
      if (!(p.u > m && p.u < 1 - m && p.v > m && p.v < 1 - m)) continue;
      if (set.under_marker(p.u, p.v, marker_margin)) continue;
      ++out.blocks_on_panel;
      const double valid_fraction = bvalid.at<float>(by, bx);
      if (valid_fraction < 0.5) {
        ++out.blocks_clipped;
        continue;
      }
      const double zr = bre.at<float>(by, bx), zi = bim.at<float>(by, bx);
      const double a = bmean.at<float>(by, bx) / valid_fraction;
      // |z| = (K/2) * 3 b (three channels summed) and a is the per-channel mean.
      const double modulation = std::hypot(zr, zi) / (1.5 * K) / std::max(a, 1e-6);
      if (!(modulation >= options.min_modulation)) {
        ++out.blocks_low_modulation;
        continue;
      }
      double psi = std::atan2(zi, zr) / two_pi;
      psi -= std::floor(psi);
      out.samples.push_back({float(p.u), float(p.v), float(psi), float(modulation)});
      modulations.push_back(float(modulation));
      for (int k = 0; k < K; ++k) {
        const double e = blevel[size_t(k)].at<float>(by, bx) / valid_fraction - a;
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
