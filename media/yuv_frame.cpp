#include "media/yuv_frame.hpp"

#include <algorithm>
#include <cmath>

namespace lfd::media {

YuvToRgb yuv_to_rgb_coefficients(YuvMatrix m, YuvRange r) {
  // E'y = Kr R + (1 - Kr - Kb) G + Kb B; Cb = (B - Y) / (2 (1 - Kb)); Cr = (R - Y) / (2 (1 - Kr)).
  const double kr = m == YuvMatrix::kBt601 ? 0.299 : m == YuvMatrix::kBt709 ? 0.2126 : 0.2627;
  const double kb = m == YuvMatrix::kBt601 ? 0.114 : m == YuvMatrix::kBt709 ? 0.0722 : 0.0593;
  const double kg = 1 - kr - kb;
  const bool full = r == YuvRange::kFull;
  // Samples / 255 -> Y in [0, 1], Cb/Cr in [-0.5, 0.5].
  const double y_scale = full ? 1.0 : 255.0 / 219.0, c_scale = full ? 1.0 : 255.0 / 224.0;
  const double y_off = full ? 0.0 : 16.0 / 255.0, c_off = 128.0 / 255.0;
  const double r_cr = 2 * (1 - kr), b_cb = 2 * (1 - kb);
  const double g_cb = -b_cb * kb / kg, g_cr = -r_cr * kr / kg;
  YuvToRgb t;
  // Columns: Y, Cb, Cr.
  t.matrix = {float(y_scale), float(y_scale), float(y_scale),
              0.f, float(g_cb * c_scale), float(b_cb * c_scale),
              float(r_cr * c_scale), float(g_cr * c_scale), 0.f};
  t.offset = {float(y_off), float(c_off), float(c_off)};
  return t;
}

namespace {

// GL's linear filter with clamp-to-edge at luma pixel (x, y)'s centre on a plane scaled by
// (plane / picture).
float sample_bilinear(const YuvPlane& p, double u, double v) {
  const double fx = std::clamp(u * p.width - 0.5, 0.0, double(p.width - 1));
  const double fy = std::clamp(v * p.height - 0.5, 0.0, double(p.height - 1));
  const int x0 = int(fx), y0 = int(fy);
  const int x1 = std::min(x0 + 1, p.width - 1), y1 = std::min(y0 + 1, p.height - 1);
  const double ax = fx - x0, ay = fy - y0;
  auto at = [&](int x, int y) { return double(p.data[size_t(y) * p.stride + x]); };
  const double top = at(x0, y0) * (1 - ax) + at(x1, y0) * ax;
  const double bottom = at(x0, y1) * (1 - ax) + at(x1, y1) * ax;
  return float((top * (1 - ay) + bottom * ay) / 255.0);
}

}  // namespace

Image8 yuv_to_rgb(const YuvFrame& frame) {
  const YuvToRgb t = yuv_to_rgb_coefficients(frame.matrix, frame.range);
  Image8 out(frame.width, frame.height, 3);
#pragma omp parallel for
  for (int y = 0; y < frame.height; ++y) {
    const double v = (y + 0.5) / frame.height;
    for (int x = 0; x < frame.width; ++x) {
      const double u = (x + 0.5) / frame.width;
      const float yuv[3] = {frame.planes[0].data[size_t(y) * frame.planes[0].stride + x] / 255.f - t.offset[0],
                            sample_bilinear(frame.planes[1], u, v) - t.offset[1],
                            sample_bilinear(frame.planes[2], u, v) - t.offset[2]};
      for (int c = 0; c < 3; ++c) {
        const float value = t.matrix[c] * yuv[0] + t.matrix[3 + c] * yuv[1] + t.matrix[6 + c] * yuv[2];
        out.at(x, y, c) = uint8_t(std::lround(std::clamp(value, 0.f, 1.f) * 255.f));
      }
    }
  }
  return out;
}

}  // namespace lfd::media
