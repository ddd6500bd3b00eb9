// Stage 3 of the reference forward pass (forward.cu renderCUDA; docs/rendering.md "The CPU
// reference rasterizer"). Each pixel walks its tile's list front to back exactly as the CUDA thread
// does; here the loop runs Gaussian-outer, pixel-inner over a tile for cache locality, which leaves
// every pixel's sequence of operations unchanged.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/blend.hpp"

namespace lfd::render {
namespace {

constexpr float kMaxAlpha = 0.99f;
constexpr float kMinAlpha = 1.0f / 255.0f;
constexpr float kMinTransmittance = 0.0001f;

// Pixel columns of tile row `y` that may reach alpha >= 1/255: the solution interval of the
// quadratic power(dx) >= ln(1/(255 o)) widened by a safety margin (in power and one pixel), so
// no pixel the reference would blend is skipped; the exact per-pixel test follows.
bool row_span(const ProjectedGaussian& g, float y, int x0, int x1, int* lo, int* hi) {
  const double a = g.conic.x, b = g.conic.y, c = g.conic.z;
  const double dy = double(g.mean_px.y) - y;
  const double threshold = std::log(1.0 / (255.0 * std::max(double(g.opacity), 1e-30))) - 0.01;
  // -0.5 a dx^2 - b dy dx - 0.5 c dy^2 >= threshold
  const double qa = 0.5 * a, qb = b * dy, qc = 0.5 * c * dy * dy + threshold;
  if (!(qa > 0.0)) { *lo = x0; *hi = x1; return true; }
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc < 0.0) return false;
  const double s = std::sqrt(disc);
  const double dx_lo = (-qb - s) / (2.0 * qa), dx_hi = (-qb + s) / (2.0 * qa);
  // dx = mean.x - px  =>  px in [mean.x - dx_hi, mean.x - dx_lo]
  const double p_lo = std::floor(g.mean_px.x - dx_hi) - 1.0, p_hi = std::ceil(g.mean_px.x - dx_lo) + 1.0;
  *lo = int(std::max<double>(x0, p_lo));
  *hi = int(std::min<double>(x1, p_hi));
  return *lo <= *hi;
}

}  // namespace

RasterImage blend(const std::vector<ProjectedGaussian>& projected, const TileBins& bins, int width,
                  int height, const glm::vec3& background, std::span<const uint8_t> pixel_mask) {
  RasterImage img;
  img.width = width;
  img.height = height;
  img.rgb.assign(size_t(width) * height * 3, 0.0f);
  img.transmittance.assign(size_t(width) * height, 1.0f);
  const int tiles = bins.tiles_x * bins.tiles_y;
  const bool masked = !pixel_mask.empty();
  if (masked && pixel_mask.size() != size_t(width) * height)
    throw std::invalid_argument("blend: pixel mask size differs from the image's");

#pragma omp parallel for schedule(dynamic, 1)
  for (int tile = 0; tile < tiles; ++tile) {
    const int x0 = (tile % bins.tiles_x) * kTileSize, y0 = (tile / bins.tiles_x) * kTileSize;
    const int x1 = std::min(width, x0 + kTileSize) - 1, y1 = std::min(height, y0 + kTileSize) - 1;
    float T[kTileSize * kTileSize], C[kTileSize * kTileSize * 3];
    bool done[kTileSize * kTileSize];
    std::fill(std::begin(T), std::end(T), 1.0f);
    std::fill(std::begin(C), std::end(C), 0.0f);
    std::fill(std::begin(done), std::end(done), false);
    int remaining = (x1 - x0 + 1) * (y1 - y0 + 1);
    // Masked-out pixels start done: the loop below never touches them and stops once every
    // masked-in pixel is done, as it does for all of them unmasked.
    if (masked)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
          if (!pixel_mask[size_t(y) * width + x]) {
            done[(y - y0) * kTileSize + (x - x0)] = true;
            --remaining;
          }

    for (uint32_t k = bins.range_begin[tile]; k < bins.range_begin[tile + 1] && remaining > 0; ++k) {
      const ProjectedGaussian& g = projected[bins.ids[k]];
      for (int y = y0; y <= y1; ++y) {
        int lo, hi;
        if (!row_span(g, float(y), x0, x1, &lo, &hi)) continue;
        for (int x = lo; x <= hi; ++x) {
          const int p = (y - y0) * kTileSize + (x - x0);
          if (done[p]) continue;
          const float dx = g.mean_px.x - float(x), dy = g.mean_px.y - float(y);
          const float power = -0.5f * (g.conic.x * dx * dx + g.conic.z * dy * dy) - g.conic.y * dx * dy;
          if (power > 0.0f) continue;
          const float alpha = std::min(kMaxAlpha, g.opacity * std::exp(power));
          if (alpha < kMinAlpha) continue;
          const float test_T = T[p] * (1.0f - alpha);
          if (test_T < kMinTransmittance) {
            done[p] = true;
            --remaining;
            continue;
          }
          const float w = alpha * T[p];
          C[3 * p] += g.color.x * w;
          C[3 * p + 1] += g.color.y * w;
          C[3 * p + 2] += g.color.z * w;
          T[p] = test_T;
        }
      }
    }
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const int p = (y - y0) * kTileSize + (x - x0);
        const size_t o = size_t(y) * width + x;
        img.transmittance[o] = T[p];
        for (int ch = 0; ch < 3; ++ch) img.rgb[3 * o + ch] = C[3 * p + ch] + T[p] * background[ch];
      }
  }
  return img;
}

}  // namespace lfd::render
