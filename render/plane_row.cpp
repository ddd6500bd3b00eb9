// A plane row blended once for all rays of a panel row (render/plane_row.hpp).
#include "render/plane_row.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace lfd::render {
namespace {

// RGBT of one texel as floats, and whether it is empty (0, 0, 0, T = 1): the emptiness test of
// make_sweeping_planes (render/sweeping_planes.cpp).
struct U8Source {
  const uint8_t* data;
  const float* unit = units().data();
  // v / 255 as the swizzle's table has it, without a division per channel.
  static const std::array<float, 256>& units() {
    static const std::array<float, 256> table = [] {
      std::array<float, 256> t{};
      for (int i = 0; i < 256; ++i) t[size_t(i)] = float(i) / 255.0f;
      return t;
    }();
    return table;
  }
  bool load(size_t texel, float out[4]) const {
    const uint8_t* t = data + texel * 4;
    out[0] = unit[t[0]];
    out[1] = unit[t[1]];
    out[2] = unit[t[2]];
    out[3] = unit[t[3]];
    return !(t[0] == 0 && t[1] == 0 && t[2] == 0 && t[3] == 255);
  }
};
struct F32Source {
  const float* data;
  bool load(size_t texel, float out[4]) const {
    std::memcpy(out, data + texel * 4, 4 * sizeof(float));
    return !(out[0] == 0.0f && out[1] == 0.0f && out[2] == 0.0f && out[3] == 1.0f);
  }
};

template <typename Source>
void blend_columns(const Source& src, const SweepingPlanes& planes, int k, int row0, int row1, float w0, float w1,
                   BlendedPlaneRow& out) {
  const int wp = planes.width, hp = planes.height;
  const size_t base = size_t(k) * size_t(wp) * size_t(hp);
  const bool has0 = row0 >= 0 && row0 < hp && w0 > 0.0f, has1 = row1 >= 0 && row1 < hp && w1 > 0.0f;
  const int last = out.first_column + out.length - 1 - BlendedPlaneRow::kPad;
  float* v[4] = {out.values.data(), out.values.data() + out.stride, out.values.data() + 2 * size_t(out.stride),
                 out.values.data() + 3 * size_t(out.stride)};
  int run_start = -1, run_end = -1;
  for (int x = out.first_column + BlendedPlaneRow::kPad; x <= last; ++x) {
    float a[4] = {0, 0, 0, 1}, b[4] = {0, 0, 0, 1};
    const bool full0 = has0 && src.load(base + size_t(row0) * size_t(wp) + size_t(x), a);
    const bool full1 = has1 && src.load(base + size_t(row1) * size_t(wp) + size_t(x), b);
    const size_t i = size_t(x - out.first_column);
    if (!full0 && !full1) {
      v[0][i] = v[1][i] = v[2][i] = 0.0f;
      v[3][i] = 1.0f;
      continue;
    }
    for (int c = 0; c < 4; ++c) v[c][i] = w1 > 0.0f ? w0 * a[c] + w1 * b[c] : a[c];
    if (run_start >= 0 && x - run_end - 1 <= BlendedPlaneRow::kMergeGap) {
      run_end = x;
    } else {
      if (run_start >= 0) out.runs.push_back({run_start, run_end});
      run_start = run_end = x;
    }
  }
  if (run_start >= 0) out.runs.push_back({run_start, run_end});
}

}  // namespace

bool blend_plane_row(const SweepingPlanes& planes, int k, int row0, int row1, float fy, bool bilinear,
                     BlendedPlaneRow& out) {
  const int wp = planes.width, hp = planes.height;
  int first = wp, last = -1;
  for (int r : {row0, bilinear ? row1 : row0})
    if (r >= 0 && r < hp) {
      first = std::min(first, planes.row_first[size_t(k) * size_t(hp) + size_t(r)]);
      last = std::max(last, planes.row_last[size_t(k) * size_t(hp) + size_t(r)]);
    }
  if (first > last) return false;
  out.first_column = first - BlendedPlaneRow::kPad;
  out.length = last - first + 1 + 2 * BlendedPlaneRow::kPad;
  out.stride = BlendedPlaneRow::stride_for(planes);
  if (out.values.size() < 4 * size_t(out.stride)) out.values.resize(4 * size_t(out.stride));
  for (int c = 0; c < 4; ++c)
    for (int p = 0; p < BlendedPlaneRow::kPad; ++p) {
      const float empty = c == 3 ? 1.0f : 0.0f;
      out.values[size_t(c) * size_t(out.stride) + size_t(p)] = empty;
      out.values[size_t(c) * size_t(out.stride) + size_t(out.length - 1 - p)] = empty;
    }
  out.runs.clear();
  const float w0 = bilinear ? 1.0f - fy : 1.0f, w1 = bilinear ? fy : 0.0f;
  if (planes.precision == PlanePrecision::kU8)
    blend_columns(U8Source{planes.texels_u8.data()}, planes, k, row0, row1, w0, w1, out);
  else
    blend_columns(F32Source{planes.texels_f32.data()}, planes, k, row0, row1, w0, w1, out);
  return !out.runs.empty();
}

}  // namespace lfd::render
