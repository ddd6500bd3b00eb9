// Alg. 1 lines 6-12: swizzle blending. For quilt view j, pixel (x, y) and plane k the sampling
// point is Eq. (u_prime), which is affine in x for a fixed (j, k) and independent of j in y
// (views move horizontally only), so each output row reads one (nearest) or two (bilinear)
// rows of each plane, the same for every view. Planes are composited front to back with Eq. (alpha_blend); a pixel stops
// once its transmittance falls below half an 8-bit step (what is left cannot move an 8-bit
// output value by more than rounding), a row once all its pixels have.
#include <algorithm>
#include <array>
#include <cmath>

#include "render/swizzle_blend.hpp"

namespace lfd::render {
namespace {

constexpr float kMinTransmittance = 0.5f / 255.0f;

struct U8Texels {
  const uint8_t* data;
  std::array<float, 256> lut;
  inline void load(size_t texel, float out[4]) const {
    const uint8_t* t = data + texel * 4;
    out[0] = lut[t[0]]; out[1] = lut[t[1]]; out[2] = lut[t[2]]; out[3] = lut[t[3]];
  }
};
struct F32Texels {
  const float* data;
  inline void load(size_t texel, float out[4]) const {
    const float* t = data + texel * 4;
    out[0] = t[0]; out[1] = t[1]; out[2] = t[2]; out[3] = t[3];
  }
};

// RGBT of texel (x, row) of a plane; outside: empty (0, 0, 0, 1), as a GL clamp-to-border
// sampler with border (0, 0, 0, 1).
template <typename Texels>
inline void fetch(const Texels& tex, size_t plane_base, int width, int height, int x, int row, float out[4]) {
  if (x < 0 || x >= width || row < 0 || row >= height) {
    out[0] = out[1] = out[2] = 0.0f;
    out[3] = 1.0f;
    return;
  }
  tex.load(plane_base + size_t(row) * width + x, out);
}

// Per plane: the factors of Eq. (u_prime) that do not depend on the view or pixel.
struct PlaneMap {
  float parallax;  // (D_focal - d_k) / D_focal / ((d_k - D_forward) tan(theta'_x/2)), times dx_j
  float scale_x;   // d_k tan(theta_x/2) / ((d_k - D_forward) tan(theta'_x/2)), times u
  float scale_y;
};

// The plane rows that output row y reads (row1 = row0 for nearest) and the vertical weight.
struct PlaneRows {
  int row0, row1;
  float fy;
};

// One view's output row blended with one plane: the columns x_lo..x_hi whose samples can touch
// the plane row's non-empty texels, px = alpha + beta x. `T`, `C` are the view's row of
// transmittance and colour; `active` counts its pixels still above kMinTransmittance.
template <typename Texels, bool kBilinear>
inline void blend_view_row(const Texels& tex, size_t base, int Wp, int Hp, const PlaneRows& rows, float alpha,
                           float beta, int x_lo, int x_hi, float* T, float* C, int& active, int& views_active) {
  const int row0 = rows.row0, row1 = rows.row1;
  const float fy = rows.fy;
  for (int x = x_lo; x <= x_hi; ++x) {
    float& t = T[x];
    if (t < kMinTransmittance) continue;
    const float px = alpha + beta * float(x);
    float s[4];
    if constexpr (kBilinear) {
      const int col0 = int(std::floor(px));
      const float fx = px - float(col0);
      float a[4], b[4], c[4], d[4];
      fetch(tex, base, Wp, Hp, col0, row0, a);
      fetch(tex, base, Wp, Hp, col0 + 1, row0, b);
      fetch(tex, base, Wp, Hp, col0, row1, c);
      fetch(tex, base, Wp, Hp, col0 + 1, row1, d);
      for (int ch = 0; ch < 4; ++ch)
        s[ch] = (1.0f - fy) * ((1.0f - fx) * a[ch] + fx * b[ch]) + fy * ((1.0f - fx) * c[ch] + fx * d[ch]);
    } else {
      fetch(tex, base, Wp, Hp, int(std::floor(px + 0.5f)), row0, s);
    }
    C[3 * x] += t * s[0];
    C[3 * x + 1] += t * s[1];
    C[3 * x + 2] += t * s[2];
    t *= s[3];
    if (t < kMinTransmittance && --active == 0) --views_active;
  }
}

// Output row y of every view into its tile: the blended colour over the background.
void write_row(const QuiltGeometry& geometry, const QuiltLayout& layout, int y, const std::vector<float>& T,
               const std::vector<float>& C, const glm::vec3& background, ImageF& quilt) {
  const int W = geometry.base.width;
  for (int j = 0; j < geometry.views; ++j) {
    const int x0 = layout.tile_x(j), y0 = layout.tile_y_top_down(j);
    const float* Tj = T.data() + size_t(j) * W;
    const float* Cj = C.data() + size_t(j) * W * 3;
    for (int x = 0; x < W && x < layout.tile_width(); ++x)
      for (int ch = 0; ch < 3; ++ch) quilt.at(x0 + x, y0 + y, ch) = Cj[3 * x + ch] + Tj[x] * background[ch];
  }
}

template <typename Texels, bool kBilinear>
void swizzle_rows(const SweepingPlanes& planes, const Texels& tex, const QuiltGeometry& geometry,
                  const QuiltLayout& layout, const std::vector<PlaneMap>& maps,
                  const glm::vec3& background, ImageF& quilt) {
  const int W = geometry.base.width, H = geometry.base.height, V = geometry.views;
  const int Wp = planes.width, Hp = planes.height;
  const size_t plane_texels = size_t(Wp) * Hp;
  std::vector<float> offsets(static_cast<size_t>(V));
  for (int j = 0; j < V; ++j) offsets[size_t(j)] = geometry.view_offset(j);
  // One job = output row y of every view: the plane rows it reads do not depend on the view,
  // so each plane row is fetched into cache once and reused by all V views.
#pragma omp parallel
  {
    std::vector<float> T(static_cast<size_t>(V) * W), C(static_cast<size_t>(V) * W * 3);
    std::vector<int> active(static_cast<size_t>(V));
#pragma omp for schedule(dynamic, 2)
    for (int y = 0; y < H; ++y) {
      std::fill(T.begin(), T.end(), 1.0f);
      std::fill(C.begin(), C.end(), 0.0f);
      std::fill(active.begin(), active.end(), W);
      int views_active = V;
      const float v_ndc = (2.0f * y + 1.0f) / float(H) - 1.0f;
      for (int k = 0; k < planes.count && views_active > 0; ++k) {
        const PlaneMap& m = maps[size_t(k)];
        const float py = ((m.scale_y * v_ndc + 1.0f) * float(Hp) - 1.0f) * 0.5f;
        PlaneRows rows;
        rows.row0 = kBilinear ? int(std::floor(py)) : int(std::floor(py + 0.5f));
        rows.row1 = kBilinear ? rows.row0 + 1 : rows.row0;
        rows.fy = py - float(rows.row0);
        int first = Wp, last = -1;
        for (int r : {rows.row0, rows.row1})
          if (r >= 0 && r < Hp) {
            first = std::min(first, planes.row_first[size_t(k) * Hp + r]);
            last = std::max(last, planes.row_last[size_t(k) * Hp + r]);
          }
        if (first > last) continue;
        const size_t base = size_t(k) * plane_texels;
        const float step = 2.0f * m.scale_x / float(W);
        const float beta = step * float(Wp) * 0.5f;
        for (int j = 0; j < V; ++j) {
          if (active[size_t(j)] == 0) continue;
          // u'(x) = u_left + step (x + 0.5); plane pixel px = ((u' + 1) Wp - 1) / 2 = alpha + beta x.
          const float u_left = offsets[size_t(j)] * m.parallax - m.scale_x;
          const float alpha = ((u_left + 0.5f * step + 1.0f) * float(Wp) - 1.0f) * 0.5f;
          // Output columns whose samples can touch texels [first - 1, last + 1].
          const float xa = (float(first) - 1.5f - alpha) / beta, xb = (float(last) + 1.5f - alpha) / beta;
          const int x_lo = std::max(0, int(std::floor(std::min(xa, xb))));
          const int x_hi = std::min(W - 1, int(std::ceil(std::max(xa, xb))));
          blend_view_row<Texels, kBilinear>(tex, base, Wp, Hp, rows, alpha, beta, x_lo, x_hi,
                                            T.data() + size_t(j) * W, C.data() + size_t(j) * W * 3,
                                            active[size_t(j)], views_active);
        }
      }
      write_row(geometry, layout, y, T, C, background, quilt);
    }
  }
}

}  // namespace

void swizzle_blend(const SweepingPlanes& planes, const QuiltGeometry& geometry,
                   const ReferenceCamera& ref, const QuiltLayout& layout, PlaneFilter filter,
                   const glm::vec3& background, ImageF& quilt) {
  // Eq. (u_prime) split per plane: u' = dx_j * parallax_k + scale_k * u (checked against
  // plane_coordinate_x by the tests through the end-to-end quilt).
  std::vector<PlaneMap> maps(size_t(planes.count));
  const float df = geometry.focal_distance;
  const float tan_x = geometry.base.tan_half_fov_x(), tan_y = geometry.base.tan_half_fov_y();
  const float tan_rx = ref.camera.tan_half_fov_x(), tan_ry = ref.camera.tan_half_fov_y();
  for (int k = 0; k < planes.count; ++k) {
    const float d = planes.plane_depth[size_t(k)], depth_ref = d - ref.d_forward_eff;
    maps[size_t(k)] = {(df - d) / df / (depth_ref * tan_rx), d * tan_x / (depth_ref * tan_rx),
                       d * tan_y / (depth_ref * tan_ry)};
  }
  const bool bilinear = filter == PlaneFilter::kBilinear;
  if (planes.precision == PlanePrecision::kU8) {
    U8Texels tex{planes.texels_u8.data(), {}};
    for (int i = 0; i < 256; ++i) tex.lut[size_t(i)] = float(i) / 255.0f;
    if (bilinear) swizzle_rows<U8Texels, true>(planes, tex, geometry, layout, maps, background, quilt);
    else swizzle_rows<U8Texels, false>(planes, tex, geometry, layout, maps, background, quilt);
  } else {
    const F32Texels tex{planes.texels_f32.data()};
    if (bilinear) swizzle_rows<F32Texels, true>(planes, tex, geometry, layout, maps, background, quilt);
    else swizzle_rows<F32Texels, false>(planes, tex, geometry, layout, maps, background, quilt);
  }
}

}  // namespace lfd::render
