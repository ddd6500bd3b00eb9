// Single rays through the sweeping planes (render/plane_rays.hpp). A row of rays goes through
// the planes front to back as the swizzle's rows do: per plane the plane row it reads and that
// row's non-empty columns once, then, per bin of camera offsets, only the rays whose sample can
// reach those columns (a window of the bin's u-sorted rays), each stopping below the swizzle's
// transmittance.
#include "render/plane_rays.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace lfd::render {
namespace {

constexpr float kMinTransmittance = 0.5f / 255.0f;  // the swizzle's (render/swizzle_blend.cpp)

struct U8Texels {
  const uint8_t* data;
  std::array<float, 256> lut;
  float at(size_t texel, int ch) const { return lut[data[texel * 4 + size_t(ch)]]; }
};
struct F32Texels {
  const float* data;
  float at(size_t texel, int ch) const { return data[texel * 4 + size_t(ch)]; }
};

// Rays of one row whose offsets lie in [dx_min, dx_max], in order of u.
struct OffsetBin {
  float dx_min = 0, dx_max = 0;
  std::vector<uint32_t> rays;
};

// Channel `ch` and transmittance of texel (x, row) of the plane at `base`; outside the plane:
// empty (0, T = 1), as the swizzle's clamp-to-border.
template <typename Texels>
inline void fetch(const Texels& tex, size_t base, int w, int h, int x, int row, int ch, float& c, float& t) {
  if (x < 0 || x >= w || row < 0 || row >= h) {
    c = 0.0f;
    t = 1.0f;
    return;
  }
  const size_t texel = base + size_t(row) * size_t(w) + size_t(x);
  c = tex.at(texel, ch);
  t = tex.at(texel, 3);
}

// Channel `ch` and transmittance of a plane at (px, the rows of py): nearest, or bilinear with
// the swizzle's weights.
template <typename Texels, bool kBilinear>
inline void sample_plane(const Texels& tex, size_t base, int wp, int hp, int row0, int row1, float fy, float px,
                         int ch, float& c, float& a) {
  if constexpr (kBilinear) {
    const int col0 = int(std::floor(px));
    const float fx = px - float(col0);
    float c00, t00, c10, t10, c01, t01, c11, t11;
    fetch(tex, base, wp, hp, col0, row0, ch, c00, t00);
    fetch(tex, base, wp, hp, col0 + 1, row0, ch, c10, t10);
    fetch(tex, base, wp, hp, col0, row1, ch, c01, t01);
    fetch(tex, base, wp, hp, col0 + 1, row1, ch, c11, t11);
    c = (1.0f - fy) * ((1.0f - fx) * c00 + fx * c10) + fy * ((1.0f - fx) * c01 + fx * c11);
    a = (1.0f - fy) * ((1.0f - fx) * t00 + fx * t10) + fy * ((1.0f - fx) * t01 + fx * t11);
  } else {
    fetch(tex, base, wp, hp, int(std::floor(px + 0.5f)), row0, ch, c, a);
  }
}

// The rays binned by their camera offset: a bin's narrow range of dx narrows the window of u from
// which a plane's non-empty span can be reached (the swizzle's per-view column range, for a
// continuum of views).
constexpr int kOffsetBins = 16;
std::array<OffsetBin, kOffsetBins> bin_by_offset(const std::vector<PlaneRay>& rays, float max_abs_dx) {
  std::array<OffsetBin, kOffsetBins> bins;
  for (size_t i = 0; i < rays.size(); ++i) {
    const float dx = rays[i].dx;
    const int b =
        max_abs_dx > 0.0f ? std::clamp(int((dx / max_abs_dx + 1.0f) * 0.5f * kOffsetBins), 0, kOffsetBins - 1) : 0;
    OffsetBin& bin = bins[size_t(b)];
    if (bin.rays.empty()) bin.dx_min = bin.dx_max = dx;
    bin.dx_min = std::min(bin.dx_min, dx);
    bin.dx_max = std::max(bin.dx_max, dx);
    bin.rays.push_back(uint32_t(i));
  }
  return bins;
}

}  // namespace

PlaneRays::PlaneRays(const SweepingPlanes& planes, const QuiltGeometry& geometry, const ReferenceCamera& ref,
                     PlaneFilter filter, const glm::vec3& background)
    : planes_(planes), filter_(filter), background_(background) {
  // Eq. (u_prime) is affine in dx and u: its two slopes from the one definition.
  maps_.reserve(size_t(planes.count));
  for (int k = 0; k < planes.count; ++k) {
    const float d = planes.plane_depth[size_t(k)];
    maps_.push_back({plane_coordinate_x_at(geometry, ref, 1.0f, 0.0f, d), plane_coordinate_x_at(geometry, ref, 0.0f, 1.0f, d),
                     plane_coordinate_y(geometry, ref, 1.0f, d)});
  }
}

template <typename Texels, bool kBilinear>
void PlaneRays::composite(const Texels& tex, float v_ndc, float max_abs_dx, const std::vector<PlaneRay>& rays,
                          std::vector<float>& out) const {
  const int wp = planes_.width, hp = planes_.height;
  const size_t plane_texels = size_t(wp) * size_t(hp);
  const size_t n = rays.size();
  // Front to back with every ray's transmittance at hand, plane by plane as the swizzle does, so
  // each plane touches only the rays whose sample can reach its non-empty columns.
  std::vector<float> colour(n, 0.0f), trans(n, 1.0f);
  size_t active = n;
  const std::array<OffsetBin, kOffsetBins> bins = bin_by_offset(rays, max_abs_dx);
  for (int k = 0; k < planes_.count && active > 0; ++k) {
    const PlaneMap& m = maps_[size_t(k)];
    const float py = ((m.scale_y * v_ndc + 1.0f) * float(hp) - 1.0f) * 0.5f;
    const int row0 = kBilinear ? int(std::floor(py)) : int(std::floor(py + 0.5f));
    const int row1 = kBilinear ? row0 + 1 : row0;
    const float fy = py - float(row0);
    int first = wp, last = -1;
    for (int r : {row0, row1})
      if (r >= 0 && r < hp) {
        first = std::min(first, planes_.row_first[size_t(k) * size_t(hp) + size_t(r)]);
        last = std::max(last, planes_.row_last[size_t(k) * size_t(hp) + size_t(r)]);
      }
    if (first > last) continue;
    // px = ((dx parallax + u scale_x + 1) wp - 1) / 2 must reach [first - 1.5, last + 1.5], i.e.
    // dx parallax + u scale_x in [lo, hi]; per bin of offsets that bounds u, and each bin's rays
    // are sorted by u.
    const float lo = (2.0f * (float(first) - 1.5f) + 1.0f) / float(wp) - 1.0f;
    const float hi = (2.0f * (float(last) + 1.5f) + 1.0f) / float(wp) - 1.0f;
    const size_t base = size_t(k) * plane_texels;
    for (const OffsetBin& bin : bins) {
      if (bin.rays.empty()) continue;
      const float m0 = std::min(bin.dx_min * m.parallax, bin.dx_max * m.parallax);
      const float m1 = std::max(bin.dx_min * m.parallax, bin.dx_max * m.parallax);
      const float ua = (lo - m1) / m.scale_x, ub = (hi - m0) / m.scale_x;
      const float u_lo = std::min(ua, ub) - 1e-4f, u_hi = std::max(ua, ub) + 1e-4f;
      const auto begin = std::lower_bound(bin.rays.begin(), bin.rays.end(), u_lo,
                                          [&](uint32_t r, float u) { return rays[r].u_ndc < u; });
      for (auto it = begin; it != bin.rays.end() && rays[*it].u_ndc <= u_hi; ++it) {
        float& t = trans[*it];
        if (t < kMinTransmittance) continue;
        const PlaneRay& ray = rays[*it];
        const float px = ((ray.dx * m.parallax + ray.u_ndc * m.scale_x + 1.0f) * float(wp) - 1.0f) * 0.5f;
        if (!(px >= float(first) - 1.5f && px <= float(last) + 1.5f)) continue;  // empty there
        float c, a;
        sample_plane<Texels, kBilinear>(tex, base, wp, hp, row0, row1, fy, px, ray.channel, c, a);
        colour[*it] += t * c;
        t *= a;
        if (t < kMinTransmittance) --active;
      }
    }
  }
  out.resize(n);
  for (size_t i = 0; i < n; ++i) out[i] = colour[i] + trans[i] * background_[rays[i].channel];
}

void PlaneRays::composite_row(float v_ndc_top_down, float max_abs_dx, const std::vector<PlaneRay>& rays,
                              std::vector<float>& out) const {
  const bool bilinear = filter_ == PlaneFilter::kBilinear;
  if (planes_.precision == PlanePrecision::kU8) {
    U8Texels tex{planes_.texels_u8.data(), {}};
    for (int i = 0; i < 256; ++i) tex.lut[size_t(i)] = float(i) / 255.0f;
    if (bilinear) composite<U8Texels, true>(tex, v_ndc_top_down, max_abs_dx, rays, out);
    else composite<U8Texels, false>(tex, v_ndc_top_down, max_abs_dx, rays, out);
  } else {
    const F32Texels tex{planes_.texels_f32.data()};
    if (bilinear) composite<F32Texels, true>(tex, v_ndc_top_down, max_abs_dx, rays, out);
    else composite<F32Texels, false>(tex, v_ndc_top_down, max_abs_dx, rays, out);
  }
}

}  // namespace lfd::render
