// Single rays through the sweeping planes (render/plane_rays.hpp). Per row the plane rows each
// plane is read at and their non-empty column span are found once; per ray only the column and
// the blend remain, and a plane whose span the ray's sample cannot touch is skipped as empty.
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

// Where one row of rays reads plane k: rows row0/row1 (equal for nearest), vertical weight,
// and the columns [first, last] that hold anything in them (first > last: nothing).
struct PlaneRowSpan {
  int row0, row1;
  float fy;
  int first, last;
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
void PlaneRays::composite(const Texels& tex, float v_ndc, const std::vector<PlaneRay>& rays,
                          std::vector<float>& out) const {
  const int wp = planes_.width, hp = planes_.height;
  const size_t plane_texels = size_t(wp) * size_t(hp);
  std::vector<PlaneRowSpan> spans(size_t(planes_.count));
  for (int k = 0; k < planes_.count; ++k) {
    const float py = ((maps_[size_t(k)].scale_y * v_ndc + 1.0f) * float(hp) - 1.0f) * 0.5f;
    PlaneRowSpan& s = spans[size_t(k)];
    s.row0 = kBilinear ? int(std::floor(py)) : int(std::floor(py + 0.5f));
    s.row1 = kBilinear ? s.row0 + 1 : s.row0;
    s.fy = py - float(s.row0);
    s.first = wp;
    s.last = -1;
    for (int r : {s.row0, s.row1})
      if (r >= 0 && r < hp) {
        s.first = std::min(s.first, planes_.row_first[size_t(k) * size_t(hp) + size_t(r)]);
        s.last = std::max(s.last, planes_.row_last[size_t(k) * size_t(hp) + size_t(r)]);
      }
  }
  out.resize(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    const PlaneRay& ray = rays[i];
    float colour = 0.0f, t = 1.0f;
    for (int k = 0; k < planes_.count && t >= kMinTransmittance; ++k) {
      const PlaneRowSpan& s = spans[size_t(k)];
      const PlaneMap& m = maps_[size_t(k)];
      const float px = ((ray.dx * m.parallax + ray.u_ndc * m.scale_x + 1.0f) * float(wp) - 1.0f) * 0.5f;
      if (!(px >= float(s.first) - 1.5f && px <= float(s.last) + 1.5f)) continue;  // empty there
      const size_t base = size_t(k) * plane_texels;
      float c, a;
      if constexpr (kBilinear) {
        const int col0 = int(std::floor(px));
        const float fx = px - float(col0);
        float c00, t00, c10, t10, c01, t01, c11, t11;
        fetch(tex, base, wp, hp, col0, s.row0, ray.channel, c00, t00);
        fetch(tex, base, wp, hp, col0 + 1, s.row0, ray.channel, c10, t10);
        fetch(tex, base, wp, hp, col0, s.row1, ray.channel, c01, t01);
        fetch(tex, base, wp, hp, col0 + 1, s.row1, ray.channel, c11, t11);
        c = (1.0f - s.fy) * ((1.0f - fx) * c00 + fx * c10) + s.fy * ((1.0f - fx) * c01 + fx * c11);
        a = (1.0f - s.fy) * ((1.0f - fx) * t00 + fx * t10) + s.fy * ((1.0f - fx) * t01 + fx * t11);
      } else {
        fetch(tex, base, wp, hp, int(std::floor(px + 0.5f)), s.row0, ray.channel, c, a);
      }
      colour += t * c;
      t *= a;
    }
    out[i] = colour + t * background_[ray.channel];
  }
}

void PlaneRays::composite_row(float v_ndc_top_down, const std::vector<PlaneRay>& rays,
                              std::vector<float>& out) const {
  const bool bilinear = filter_ == PlaneFilter::kBilinear;
  if (planes_.precision == PlanePrecision::kU8) {
    U8Texels tex{planes_.texels_u8.data(), {}};
    for (int i = 0; i < 256; ++i) tex.lut[size_t(i)] = float(i) / 255.0f;
    if (bilinear) composite<U8Texels, true>(tex, v_ndc_top_down, rays, out);
    else composite<U8Texels, false>(tex, v_ndc_top_down, rays, out);
  } else {
    const F32Texels tex{planes_.texels_f32.data()};
    if (bilinear) composite<F32Texels, true>(tex, v_ndc_top_down, rays, out);
    else composite<F32Texels, false>(tex, v_ndc_top_down, rays, out);
  }
}

}  // namespace lfd::render
