#include "display/lens_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::display {

LensModel::LensModel(const DisplayCalibration& calibration, CorrectionField correction)
    : calibration_(calibration), correction_(std::move(correction)) {
  const auto& c = calibration_;
  const ShaderTerms<double> terms = shader_terms(c.geometry(), c.pitch_lpi, c.slope);
  pitch_periods_ = terms.pitch_periods;
  tilt_ = terms.tilt;
  // On a BGR panel (flipSubp) red sits at the third position and blue at the first
  // (docs/display-model.md "Vendor interlacing rules").
  if (c.flip_subp) physical_index_ = {2, 1, 0};
  // Cell offsets are in pixel units; normalise once into screen units (same section).
  for (const auto& cell : c.subpixel_cells) {
    const double w = c.screen_w, h = c.screen_h;
    cell_offsets_.push_back({ScreenUV{cell.r_x / w, cell.r_y / h},
                             ScreenUV{cell.g_x / w, cell.g_y / h},
                             ScreenUV{cell.b_x / w, cell.b_y / h}});
  }
}

double LensModel::slant_deg() const {
  return slant_deg_of_slope(calibration_.slope);
}

ScreenUV LensModel::subpixel_uv(int x, int row_top_down, int channel) const {
  ScreenUV p = pixel_uv(x, row_top_down);
  if (cell_offsets_.empty()) {
    p.u += physical_index_[channel] / (3.0 * calibration_.screen_w);
    return p;
  }
  // The cell pattern uses bottom-up row indices (the parity differs from top-down).
  const int j = calibration_.screen_h - 1 - row_top_down;
  const ScreenUV& d = cell_offsets_[size_t(cell_index(x, j)) % cell_offsets_.size()][channel];
  p.u += d.u;
  p.v += d.v;
  return p;
}

int LensModel::cell_index(int x, int j) const {
  switch (calibration_.cell_pattern_mode) {
    case 1: return (x + j) % 2;
    case 2: return x % 2;
    case 3: return (j + 2 * (x % 2)) % 4;
    case 4: return j % 2;
    default: return 0;
  }
}

void LensModel::row_view_fractions(int row_top_down, double* out) const {
  const auto& c = calibration_;
  // The same operations as subpixel_uv, phase and view_fraction, in the same order, so the
  // results are equal bit for bit (tests/display/lens_model_test.cpp); only the parts shared
  // along the row are hoisted.
  const double v = pixel_uv(0, row_top_down).v;
  if (cell_offsets_.empty()) {
    std::array<double, 3> du;
    for (int ch = 0; ch < 3; ++ch) du[size_t(ch)] = physical_index_[size_t(ch)] / (3.0 * c.screen_w);
    for (int x = 0; x < c.screen_w; ++x) {
      const double u = (x + 0.5) / c.screen_w;
      for (int ch = 0; ch < 3; ++ch) out[3 * size_t(x) + size_t(ch)] = view_fraction(phase(ScreenUV{u + du[size_t(ch)], v}));
    }
    return;
  }
  // Every cell pattern depends on x through its parity only: the row's two cells once.
  const int j = c.screen_h - 1 - row_top_down;
  const std::array<ScreenUV, 3>* cells[2] = {&cell_offsets_[size_t(cell_index(0, j)) % cell_offsets_.size()],
                                             &cell_offsets_[size_t(cell_index(1, j)) % cell_offsets_.size()]};
  for (int x = 0; x < c.screen_w; ++x) {
    const double u = (x + 0.5) / c.screen_w;
    const auto& cell = *cells[x & 1];
    for (int ch = 0; ch < 3; ++ch)
      out[3 * size_t(x) + size_t(ch)] = view_fraction(phase(ScreenUV{u + cell[size_t(ch)].u, v + cell[size_t(ch)].v}));
  }
}

double LensModel::phase(ScreenUV p) const {
  const double a = (p.u + p.v * tilt_) * pitch_periods_ - calibration_.center_periods;
  // Without a field w = 0: no call per subpixel (a + 0.0 would be a, up to the sign of a zero,
  // which no fraction sees).
  return correction_.empty() ? a : a + correction_(p.u, p.v);
}

double LensModel::view_fraction(double a) const {
  const double frac = a - std::floor(a);
  const double f = calibration_.inv_view ? 1.0 - frac : frac;
  return std::clamp(f, 1e-5, 0.999999);
}

double LensModel::phase_for_fraction(double f, double lens_index) const {
  const double frac = calibration_.inv_view ? 1.0 - f : f;
  return lens_index + (frac - std::floor(frac));
}

int LensModel::view_index(double fraction, int views) {
  return std::clamp(int(std::floor(fraction * views)), 0, views - 1);
}

}  // namespace lfd::display
