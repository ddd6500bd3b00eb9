// Alg. 1 lines 6-12: swizzle blending. For quilt view j, pixel (x, y) and plane k the sampling
// point is Eq. (u_prime), which is affine in x for a fixed (j, k) and independent of j in y
// (views move horizontally only), so each output row reads one (nearest) or two (bilinear)
// rows of each plane. Planes are composited front to back with Eq. (alpha_blend); a pixel stops
// once its transmittance falls below 1e-4, a row once all its pixels have.
#include <algorithm>
#include <array>
#include <cmath>

#include "render/g2lf.hpp"

namespace lfd::render {
namespace {

constexpr float kMinTransmittance = 1e-4f;

struct PlaneReader {
  const SweepingPlanes& planes;
  std::array<float, 256> lut{};
  explicit PlaneReader(const SweepingPlanes& p) : planes(p) {
    for (int i = 0; i < 256; ++i) lut[size_t(i)] = float(i) / 255.0f;
  }
  // RGBT of texel (x, row) of plane k; outside the plane: empty (0, 0, 0, 1), as a GL
  // clamp-to-border sampler with border (0, 0, 0, 1).
  inline void fetch(int k, int x, int row, float out[4]) const {
    if (x < 0 || x >= planes.width || row < 0 || row >= planes.height) {
      out[0] = out[1] = out[2] = 0.0f;
      out[3] = 1.0f;
      return;
    }
    const size_t o = ((size_t(k) * planes.height + row) * planes.width + x) * 4;
    if (planes.precision == PlanePrecision::kU8) {
      const uint8_t* t = &planes.texels_u8[o];
      out[0] = lut[t[0]]; out[1] = lut[t[1]]; out[2] = lut[t[2]]; out[3] = lut[t[3]];
    } else {
      const float* t = &planes.texels_f32[o];
      out[0] = t[0]; out[1] = t[1]; out[2] = t[2]; out[3] = t[3];
    }
  }
  // Non-empty column range of plane row `row` (first > last: empty).
  inline void extent(int k, int row, int* first, int* last) const {
    if (row < 0 || row >= planes.height) { *first = 1; *last = 0; return; }
    *first = planes.row_first[size_t(k) * planes.height + row];
    *last = planes.row_last[size_t(k) * planes.height + row];
  }
};

}  // namespace

void swizzle_blend(const SweepingPlanes& planes, const QuiltGeometry& geometry,
                   const ReferenceCamera& ref, const QuiltLayout& layout, PlaneFilter filter,
                   const glm::vec3& background, ImageF& quilt) {
  const int W = geometry.base.width, H = geometry.base.height;
  const float Wp = float(planes.width), Hp = float(planes.height);
  const PlaneReader reader(planes);
  const bool bilinear = filter == PlaneFilter::kBilinear;

#pragma omp parallel for schedule(dynamic, 4)
  for (long long job = 0; job < (long long)geometry.views * H; ++job) {
    const int view = int(job / H), y = int(job % H);
    std::vector<float> T(size_t(W), 1.0f), C(size_t(W) * 3, 0.0f);
    int active = W;
    const float v_ndc = (2.0f * y + 1.0f) / float(H) - 1.0f;
    for (int k = 0; k < planes.count && active > 0; ++k) {
      const float d_k = planes.plane_depth[size_t(k)];
      // Plane pixel coordinates (ndc2Pix of Eq. u_prime): px = alpha + beta * x.
      const float u_left = plane_coordinate_x(geometry, ref, view, -1.0f, d_k);
      const float u_right = plane_coordinate_x(geometry, ref, view, 1.0f, d_k);
      const float ndc_per_x = (u_right - u_left) / float(W);  // u' step per output pixel
      const float alpha = ((u_left + ndc_per_x * 0.5f + 1.0f) * Wp - 1.0f) * 0.5f;
      const float beta = ndc_per_x * Wp * 0.5f;
      const float py = ((plane_coordinate_y(geometry, ref, v_ndc, d_k) + 1.0f) * Hp - 1.0f) * 0.5f;

      int row0, row1;
      float fy = 0.0f;
      if (bilinear) {
        row0 = int(std::floor(py));
        row1 = row0 + 1;
        fy = py - float(row0);
      } else {
        row0 = row1 = int(std::floor(py + 0.5f));
      }
      int f0, l0, f1, l1;
      reader.extent(k, row0, &f0, &l0);
      reader.extent(k, row1, &f1, &l1);
      const int first = (f0 <= l0 && f1 <= l1) ? std::min(f0, f1) : (f0 <= l0 ? f0 : f1);
      const int last = (f0 <= l0 && f1 <= l1) ? std::max(l0, l1) : (f0 <= l0 ? l0 : l1);
      if (first > last) continue;
      // Output columns whose samples can touch texels [first - 1, last + 1].
      const float xa = (float(first) - 1.5f - alpha) / beta, xb = (float(last) + 1.5f - alpha) / beta;
      const int x_lo = std::max(0, int(std::floor(std::min(xa, xb))));
      const int x_hi = std::min(W - 1, int(std::ceil(std::max(xa, xb))));

      for (int x = x_lo; x <= x_hi; ++x) {
        if (T[size_t(x)] < kMinTransmittance) continue;
        const float px = alpha + beta * float(x);
        float s[4];
        if (bilinear) {
          const int col0 = int(std::floor(px));
          const float fx = px - float(col0);
          float a[4], b[4], c[4], d[4];
          reader.fetch(k, col0, row0, a);
          reader.fetch(k, col0 + 1, row0, b);
          reader.fetch(k, col0, row1, c);
          reader.fetch(k, col0 + 1, row1, d);
          for (int ch = 0; ch < 4; ++ch)
            s[ch] = (1.0f - fy) * ((1.0f - fx) * a[ch] + fx * b[ch]) + fy * ((1.0f - fx) * c[ch] + fx * d[ch]);
        } else {
          reader.fetch(k, int(std::floor(px + 0.5f)), row0, s);
        }
        float& t = T[size_t(x)];
        C[3 * size_t(x)] += t * s[0];
        C[3 * size_t(x) + 1] += t * s[1];
        C[3 * size_t(x) + 2] += t * s[2];
        t *= s[3];
        if (t < kMinTransmittance) --active;
      }
    }
    const int x0 = layout.tile_x(view), y0 = layout.tile_y_top_down(view);
    for (int x = 0; x < W && x < layout.tile_width(); ++x)
      for (int ch = 0; ch < 3; ++ch)
        quilt.at(x0 + x, y0 + y, ch) = C[3 * size_t(x) + ch] + T[size_t(x)] * background[ch];
  }
}

}  // namespace lfd::render
