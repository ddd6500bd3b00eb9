#include "voxel/antialias_downsample.hpp"

#include <algorithm>
#include <cmath>

namespace lfd::voxel {

namespace {

struct Taps {
  int first = 0;
  std::vector<float> weights;
};

// The triangle filter's taps of each output sample along one axis.
std::vector<Taps> triangle_taps(int in_size, int out_size) {
  const double scale = double(in_size) / double(out_size);
  const double support = std::max(1.0, scale);
  std::vector<Taps> taps(static_cast<size_t>(out_size));
  for (int o = 0; o < out_size; ++o) {
    const double center = (o + 0.5) * scale;  // in input pixel units, pixel j centred at j + 0.5
    const int lo = std::max(0, int(std::floor(center - support)));
    const int hi = std::min(in_size - 1, int(std::ceil(center + support)));
    Taps& t = taps[size_t(o)];
    t.first = lo;
    double sum = 0.0;
    for (int j = lo; j <= hi; ++j) {
      const double w = std::max(0.0, 1.0 - std::abs(j + 0.5 - center) / support);
      t.weights.push_back(float(w));
      sum += w;
    }
    for (float& w : t.weights) w = float(w / sum);
  }
  return taps;
}

}  // namespace

std::vector<float> antialias_downsample(const std::vector<float>& in, int width, int height, int channels,
                                        int out_width, int out_height) {
  const auto tx = triangle_taps(width, out_width);
  const auto ty = triangle_taps(height, out_height);
  const size_t c = size_t(channels);
  std::vector<float> rows(size_t(out_width) * size_t(height) * c, 0.0f);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < out_width; ++x)
      for (size_t k = 0; k < tx[size_t(x)].weights.size(); ++k) {
        const float w = tx[size_t(x)].weights[k];
        const size_t src = (size_t(y) * size_t(width) + size_t(tx[size_t(x)].first) + k) * c;
        for (size_t ch = 0; ch < c; ++ch) rows[(size_t(y) * size_t(out_width) + size_t(x)) * c + ch] += w * in[src + ch];
      }
  std::vector<float> out(size_t(out_width) * size_t(out_height) * c, 0.0f);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < out_height; ++y)
    for (size_t k = 0; k < ty[size_t(y)].weights.size(); ++k) {
      const float w = ty[size_t(y)].weights[k];
      const size_t src_row = (size_t(ty[size_t(y)].first) + k) * size_t(out_width) * c;
      for (size_t i = 0; i < size_t(out_width) * c; ++i) out[size_t(y) * size_t(out_width) * c + i] += w * rows[src_row + i];
    }
  return out;
}

}  // namespace lfd::voxel
