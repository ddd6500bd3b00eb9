#include "render/image_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "util/error.hpp"

namespace lfd::render {
namespace {

void check_same(const ImageF& a, const ImageF& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw_input_error("images differ in size: {}x{}x{} vs {}x{}x{}", a.width, a.height, a.channels,
                      b.width, b.height, b.channels);
  if (a.empty()) throw_input_error("images are empty");
}

// Separable 'valid' Gaussian filter of one channel plane (w x h) with a window of size n.
std::vector<double> filter_valid(const std::vector<double>& src, int w, int h, const std::vector<double>& k,
                                 int* ow, int* oh) {
  const int n = int(k.size());
  const int vw = w - n + 1, vh = h - n + 1;
  std::vector<double> tmp(size_t(vw) * h), out(size_t(vw) * vh);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < vw; ++x) {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += k[size_t(i)] * src[size_t(y) * w + x + i];
      tmp[size_t(y) * vw + x] = s;
    }
#pragma omp parallel for schedule(static)
  for (int y = 0; y < vh; ++y)
    for (int x = 0; x < vw; ++x) {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += k[size_t(i)] * tmp[size_t(y + i) * vw + x];
      out[size_t(y) * vw + x] = s;
    }
  *ow = vw;
  *oh = vh;
  return out;
}

}  // namespace

double psnr(const ImageF& a, const ImageF& b) {
  check_same(a, b);
  double se = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = double(a.pixels[i]) - double(b.pixels[i]);
    se += d * d;
  }
  const double mse = se / double(a.pixels.size());
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(1.0 / mse);
}

double ssim(const ImageF& a, const ImageF& b) {
  check_same(a, b);
  const int n = std::min({11, a.width, a.height});
  std::vector<double> k(static_cast<size_t>(n));
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = i - (n - 1) / 2.0;
    k[size_t(i)] = std::exp(-x * x / (2.0 * 1.5 * 1.5));
    sum += k[size_t(i)];
  }
  for (auto& v : k) v /= sum;
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  const int w = a.width, h = a.height;
  double total = 0.0;
  for (int ch = 0; ch < a.channels; ++ch) {
    std::vector<double> x(size_t(w) * h), y(size_t(w) * h), xx(x.size()), yy(x.size()), xy(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      x[i] = a.pixels[i * a.channels + ch];
      y[i] = b.pixels[i * b.channels + ch];
      xx[i] = x[i] * x[i];
      yy[i] = y[i] * y[i];
      xy[i] = x[i] * y[i];
    }
    int vw, vh;
    const auto mx = filter_valid(x, w, h, k, &vw, &vh), my = filter_valid(y, w, h, k, &vw, &vh);
    const auto sxx = filter_valid(xx, w, h, k, &vw, &vh), syy = filter_valid(yy, w, h, k, &vw, &vh);
    const auto sxy = filter_valid(xy, w, h, k, &vw, &vh);
    double s = 0.0;
    for (size_t i = 0; i < mx.size(); ++i) {
      const double vx = sxx[i] - mx[i] * mx[i], vy = syy[i] - my[i] * my[i], cxy = sxy[i] - mx[i] * my[i];
      s += ((2.0 * mx[i] * my[i] + c1) * (2.0 * cxy + c2)) /
           ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    }
    total += s / double(mx.size());
  }
  return total / double(a.channels);
}

}  // namespace lfd::render
