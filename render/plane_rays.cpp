// Single rays through the sweeping planes (render/plane_rays.hpp; docs/performance.md "Where the
// direct pass's time went"). A row of rays goes through the planes front to back, plane by plane
// as the swizzle's rows do, every ray's colour and transmittance at hand:
// - the rays are grouped once per row into bins of camera offset, in order of u within a bin
//   (a counting sort; they arrive in order of u), their fields in arrays of their own;
// - per plane the two plane rows the row reads are blended once (render/plane_row.hpp) and
//   their non-empty runs listed;
// - per bin and run, the rays whose sample can reach the run form a window of the bin's u
//   (Eq. (u_prime) is affine in dx and u), found by a galloping search from the previous
//   window's end; only those are sampled (render/plane_samples.hpp), each stopping below the
//   swizzle's transmittance.
#include "render/plane_rays.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "util/error.hpp"

namespace lfd::render {
namespace {

// Bins of camera offset over [-max |dx|, max |dx|]: a bin's narrow range of dx narrows the window
// of u from which a run can be reached (the swizzle's per-view column range, for a continuum of
// views).
constexpr int kOffsetBins = 8;
constexpr size_t kJoinSlots = 8;
// A bin closes up over its stopped rays once 1 / kCompactWhenStopped of it has stopped, if it
// has kCompactFrom rays or more and enough planes are still to come (kCompactCost: what closing
// up costs per ray of the bin, in sampled lanes; composite_plane).
constexpr size_t kCompactWhenStopped = 16;
constexpr size_t kCompactCost = 4;
constexpr size_t kCompactFrom = 32;

// Texel access for the one-ray definition (composite_ray).
struct U8Texels {
  const uint8_t* data;
  float at(size_t texel, int ch) const { return float(data[texel * 4 + size_t(ch)]) / 255.0f; }
};
struct F32Texels {
  const float* data;
  float at(size_t texel, int ch) const { return data[texel * 4 + size_t(ch)]; }
};

// Channel `ch` and transmittance of texel (x, row) of the plane at `base`; outside the plane:
// empty (0, T = 1), as the swizzle's clamp-to-border.
template <typename Texels>
void fetch(const Texels& tex, size_t base, int w, int h, int x, int row, int ch, float& c, float& t) {
  if (x < 0 || x >= w || row < 0 || row >= h) {
    c = 0.0f;
    t = 1.0f;
    return;
  }
  const size_t texel = base + size_t(row) * size_t(w) + size_t(x);
  c = tex.at(texel, ch);
  t = tex.at(texel, 3);
}

// One ray's colour and transmittance after every plane.
template <typename Texels>
std::array<float, 2> composite_one(const Texels& tex, const SweepingPlanes& planes, int k_count, const auto& rows_of,
                    const auto& column_of, int ch, bool bilinear) {
  const int wp = planes.width, hp = planes.height;
  float colour = 0.0f, trans = 1.0f;
  for (int k = 0; k < k_count && trans >= kPlaneRayMinTransmittance; ++k) {
    const auto rows = rows_of(k);
    const float px = column_of(k);
    const size_t base = size_t(k) * size_t(wp) * size_t(hp);
    float c, a;
    if (bilinear) {
      const int col0 = int(std::floor(px));
      const float fx = px - float(col0), fy = rows.fy;
      float c00, t00, c10, t10, c01, t01, c11, t11;
      fetch(tex, base, wp, hp, col0, rows.row0, ch, c00, t00);
      fetch(tex, base, wp, hp, col0 + 1, rows.row0, ch, c10, t10);
      fetch(tex, base, wp, hp, col0, rows.row1, ch, c01, t01);
      fetch(tex, base, wp, hp, col0 + 1, rows.row1, ch, c11, t11);
      c = (1.0f - fy) * ((1.0f - fx) * c00 + fx * c10) + fy * ((1.0f - fx) * c01 + fx * c11);
      a = (1.0f - fy) * ((1.0f - fx) * t00 + fx * t10) + fy * ((1.0f - fx) * t01 + fx * t11);
    } else {
      fetch(tex, base, wp, hp, int(std::floor(px + 0.5f)), rows.row0, ch, c, a);
    }
    colour += trans * c;
    trans *= a;
  }
  return {colour, trans};
}

// The first index in [lo, hi) whose u is >= value, searching from lo in growing steps (the
// windows of one bin move forward through it).
size_t gallop(const float* u, size_t lo, size_t hi, float value) {
  size_t step = 1, probe = lo;
  while (probe < hi && u[probe] < value) {
    lo = probe + 1;
    probe += step;
    step *= 2;
  }
  // The last step by halving without branches (a data-dependent branch per halving
  // mispredicts half the time).
  const float* base = u + lo;
  size_t n = std::min(probe, hi) - lo;
  if (n == 0) return lo;
  while (n > 1) {
    const size_t half = n / 2;
    base = base[half] < value ? base + half : base;
    n -= half;
  }
  return size_t(base - u) + size_t(*base < value);
}

}  // namespace

PlaneRays::PlaneRays(const SweepingPlanes& planes, const QuiltGeometry& geometry, const ReferenceCamera& ref,
                     PlaneFilter filter, const glm::vec3& background, SampleKernel kernel)
    : planes_(planes), filter_(filter), background_(background), kernel_(kernel) {
  if (!sample_kernel_available(kernel)) throw_input_error("direct pass: this CPU has no AVX2 for the avx2 sampling kernel");
  // Eq. (u_prime) is affine in dx and u: its two slopes from the one definition.
  maps_.reserve(size_t(planes.count));
  for (int k = 0; k < planes.count; ++k) {
    const float d = planes.plane_depth[size_t(k)];
    maps_.push_back({plane_coordinate_x_at(geometry, ref, 1.0f, 0.0f, d), plane_coordinate_x_at(geometry, ref, 0.0f, 1.0f, d),
                     plane_coordinate_y(geometry, ref, 1.0f, d)});
  }
}

PlaneRays::PlaneRows PlaneRays::plane_rows(int k, float v_ndc) const {
  const bool bilinear = filter_ == PlaneFilter::kBilinear;
  const float py = ((maps_[size_t(k)].scale_y * v_ndc + 1.0f) * float(planes_.height) - 1.0f) * 0.5f;
  PlaneRows r;
  r.row0 = bilinear ? int(std::floor(py)) : int(std::floor(py + 0.5f));
  r.row1 = bilinear ? r.row0 + 1 : r.row0;
  r.fy = py - float(r.row0);
  return r;
}

float PlaneRays::composite_ray(const PlaneRay& ray, float v_ndc) const {
  const int wp = planes_.width;
  const auto rows_of = [&](int k) { return plane_rows(k, v_ndc); };
  const auto column_of = [&](int k) {
    const PlaneMap& m = maps_[size_t(k)];
    return ((ray.dx * m.parallax + ray.u_ndc * m.scale_x + 1.0f) * float(wp) - 1.0f) * 0.5f;
  };
  const bool bilinear = filter_ == PlaneFilter::kBilinear;
  const std::array<float, 2> ct =
      planes_.precision == PlanePrecision::kU8
          ? composite_one(U8Texels{planes_.texels_u8.data()}, planes_, planes_.count, rows_of, column_of, ray.channel,
                          bilinear)
          : composite_one(F32Texels{planes_.texels_f32.data()}, planes_, planes_.count, rows_of, column_of,
                          ray.channel, bilinear);
  return ct[0] + ct[1] * background_[ray.channel];
}

void PlaneRays::bin_rays(const std::vector<PlaneRay>& rays, float max_abs_dx, Scratch& s) const {
  const size_t n = rays.size();
  // A bin is only a grouping (its range of dx comes from its members), so its edges need not be
  // exact: dx scaled once, no division per ray.
  const float scale = max_abs_dx > 0.0f ? 0.5f * float(kOffsetBins) / max_abs_dx : 0.0f;
  const float centre = max_abs_dx > 0.0f ? 0.5f * float(kOffsetBins) : 0.0f;
  s.bin.resize(n);
  std::array<int, kOffsetBins> count{};
  for (size_t i = 0; i < n; ++i) {
    const int b = std::clamp(int(rays[i].dx * scale + centre), 0, kOffsetBins - 1);
    s.bin[i] = uint8_t(b);
    ++count[size_t(b)];
  }
  s.bin_active.assign(count.begin(), count.end());
  s.bin_begin.assign(kOffsetBins + 1, 0);
  for (int b = 0; b < kOffsetBins; ++b) s.bin_begin[size_t(b) + 1] = s.bin_begin[size_t(b)] + uint32_t(s.bin_active[size_t(b)]);
  s.bin_end.assign(s.bin_begin.begin() + 1, s.bin_begin.end());
  s.ray.resize(n);
  s.channel.resize(n);
  // [0, n) is written below; the slots past n that the vector kernel reads are rays at the
  // plane's centre, stopped, on channel 0 (render/plane_samples.hpp).
  const size_t padded = n + kSampleWindowOverread;
  s.dx.resize(padded);
  s.u.resize(padded);
  s.channel_offset.resize(padded);
  std::fill(s.dx.begin() + std::ptrdiff_t(n), s.dx.end(), 0.0f);
  std::fill(s.u.begin() + std::ptrdiff_t(n), s.u.end(), 0.0f);
  std::fill(s.channel_offset.begin() + std::ptrdiff_t(n), s.channel_offset.end(), 0);
  s.colour.assign(padded, 0.0f);
  s.trans.assign(padded, 1.0f);
  std::fill(s.trans.begin() + std::ptrdiff_t(n), s.trans.end(), 0.0f);
  const int stride = BlendedPlaneRow::stride_for(planes_);
  std::array<uint32_t, kOffsetBins> next;
  for (int b = 0; b < kOffsetBins; ++b) next[size_t(b)] = s.bin_begin[size_t(b)];
  // Stable: within a bin the rays keep their order of u.
  for (size_t i = 0; i < n; ++i) {
    const PlaneRay& r = rays[i];
    const uint32_t slot = next[s.bin[i]]++;
    s.ray[slot] = uint32_t(i);
    s.dx[slot] = r.dx;
    s.u[slot] = r.u_ndc;
    s.channel[slot] = r.channel;
    s.channel_offset[slot] = r.channel * stride;
  }
  // Each bin's range of dx from its members, now side by side.
  s.bin_dx_min.assign(kOffsetBins, 0.0f);
  s.bin_dx_max.assign(kOffsetBins, 0.0f);
  for (int b = 0; b < kOffsetBins; ++b) {
    const size_t begin = s.bin_begin[size_t(b)], end = s.bin_begin[size_t(b) + 1];
    if (begin == end) continue;
    // Four running extremes side by side (one chain would wait on each min in turn).
    std::array<float, 4> lo, hi;
    lo.fill(s.dx[begin]);
    hi.fill(s.dx[begin]);
    size_t i = begin;
    for (; i + 4 <= end; i += 4)
      for (size_t j = 0; j < 4; ++j) {
        lo[j] = std::min(lo[j], s.dx[i + j]);
        hi[j] = std::max(hi[j], s.dx[i + j]);
      }
    for (; i < end; ++i) {
      lo[0] = std::min(lo[0], s.dx[i]);
      hi[0] = std::max(hi[0], s.dx[i]);
    }
    s.bin_dx_min[size_t(b)] = std::min(std::min(lo[0], lo[1]), std::min(lo[2], lo[3]));
    s.bin_dx_max[size_t(b)] = std::max(std::max(hi[0], hi[1]), std::max(hi[2], hi[3]));
  }
}

void PlaneRays::composite_plane(int k, Scratch& s, int& active, float* out) const {
  const PlaneMap& m = maps_[size_t(k)];
  const BlendedPlaneRow& row = s.row;
  const float half_w = 0.5f * float(planes_.width);
  // px (plane column) = ((dx parallax + u scale_x + 1) wp - 1) / 2, shifted to the buffer.
  const float ax = m.parallax * half_w, au = m.scale_x * half_w;
  const float a0 = half_w - 0.5f - float(row.first_column);
  const bool bilinear = filter_ == PlaneFilter::kBilinear;
  const size_t runs = row.runs.size();
  const SampleWindow window{row.values.data(), row.channel(3), row.length, ax, au, a0, s.dx.data(),
                      s.u.data(), s.channel_offset.data(), s.colour.data(), s.trans.data()};
  for (int b = 0; b < kOffsetBins; ++b) {
    int& bin_active = s.bin_active[size_t(b)];
    if (bin_active == 0) continue;
    const size_t begin = s.bin_begin[size_t(b)], end = s.bin_end[size_t(b)];
    const float m0 = std::min(s.bin_dx_min[size_t(b)] * ax, s.bin_dx_max[size_t(b)] * ax);
    const float m1 = std::max(s.bin_dx_min[size_t(b)] * ax, s.bin_dx_max[size_t(b)] * ax);
    const int before = bin_active;
    size_t cursor = begin;
    // Windows closer than kJoinSlots are sampled as one: the rays between them sample empty
    // texels (an exact no-op), and longer windows keep the vector lanes full.
    size_t pending0 = begin, pending1 = begin;
    const auto flush = [&] {
      if (pending1 > pending0)
        bin_active -= sample_window(kernel_, window, pending0, pending1, bilinear);
    };
    for (size_t r = 0; r < runs && cursor < end; ++r) {
      // Runs in order of u: forwards when u' grows with u.
      const auto& run = row.runs[au >= 0.0f ? r : runs - 1 - r];
      // Samples that can touch columns [a, b] lie in [a - 1.5, b + 1.5] (bilinear reads
      // floor(px) and the next column, nearest round(px)).
      const float lo = float(run[0] - row.first_column) - 1.5f - a0;
      const float hi = float(run[1] - row.first_column) + 1.5f - a0;
      float u_lo = -1e30f, u_hi = 1e30f;
      if (au != 0.0f) {
        const float ua = (lo - m1) / au, ub = (hi - m0) / au;
        u_lo = std::min(ua, ub) - 1e-4f;
        u_hi = std::max(ua, ub) + 1e-4f;
      }
      const size_t i0 = gallop(s.u.data(), cursor, end, u_lo);
      const size_t i1 = gallop(s.u.data(), i0, end, std::nextafter(u_hi, 1e30f));
      if (i0 <= pending1 + kJoinSlots) {
        pending1 = std::max(pending1, i1);
      } else {
        flush();
        pending0 = i0;
        pending1 = i1;
      }
      cursor = i1;
    }
    flush();
    active -= before - bin_active;
    // A stopped ray still takes a vector lane in every window that covers it, and the windows
    // gather where rays stop (a bin's rays that miss the scene never do): once a sixteenth of
    // the bin has stopped, its stopped rays are finished and the bin closes up (a quarter left
    // most stopped rays in the windows).
    const size_t size = end - begin;
    // Near the last plane there is nothing left to save: a stopped ray costs at most one lane
    // per plane still to come, closing up costs about kCompactCost lanes per ray of the bin.
    const size_t stopped = size - size_t(bin_active), planes_left = size_t(planes_.count - 1 - k);
    if (size >= kCompactFrom && kCompactWhenStopped * stopped > size && stopped * planes_left > kCompactCost * size)
      compact_bin(b, s, out);
  }
}

void PlaneRays::compact_bin(int b, Scratch& s, float* out) const {
  const size_t begin = s.bin_begin[size_t(b)], end = s.bin_end[size_t(b)];
  size_t kept = begin;
  for (size_t i = begin; i < end; ++i) {
    if (s.trans[i] < kPlaneRayMinTransmittance) {
      out[s.ray[i]] = finished(s, i);
      continue;
    }
    // Stable: the kept rays stay in order of u.
    s.ray[kept] = s.ray[i];
    s.dx[kept] = s.dx[i];
    s.u[kept] = s.u[i];
    s.channel[kept] = s.channel[i];
    s.channel_offset[kept] = s.channel_offset[i];
    s.colour[kept] = s.colour[i];
    s.trans[kept] = s.trans[i];
    ++kept;
  }
  s.bin_end[size_t(b)] = uint32_t(kept);
}

void PlaneRays::composite_row(float v_ndc, float max_abs_dx, const std::vector<PlaneRay>& rays,
                              std::vector<float>& out, Scratch& s) const {
  const size_t n = rays.size();
  out.resize(n);
  bin_rays(rays, max_abs_dx, s);
  int active = int(n);
  const bool bilinear = filter_ == PlaneFilter::kBilinear;
  for (int k = 0; k < planes_.count && active > 0; ++k) {
    const PlaneRows rows = plane_rows(k, v_ndc);
    if (!blend_plane_row(planes_, k, rows.row0, rows.row1, rows.fy, bilinear, s.row)) continue;
    composite_plane(k, s, active, out.data());
  }
  // The rays no compaction finished.
  for (int b = 0; b < kOffsetBins; ++b)
    for (size_t slot = s.bin_begin[size_t(b)]; slot < s.bin_end[size_t(b)]; ++slot) out[s.ray[slot]] = finished(s, slot);
}

}  // namespace lfd::render
