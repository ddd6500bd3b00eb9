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
  // 3.5: on a BGR panel (flipSubp) red sits at the third position and blue at the first.
  if (c.flip_subp) physical_index_ = {2, 1, 0};
  // 2.3: cell offsets are in pixel units; normalise once into screen units.
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

ScreenUV LensModel::pixel_uv(int x, int row_top_down) const {
  const auto& c = calibration_;
  return {(x + 0.5) / c.screen_w, 1.0 - (row_top_down + 0.5) / c.screen_h};
}

ScreenUV LensModel::subpixel_uv(int x, int row_top_down, int channel) const {
  ScreenUV p = pixel_uv(x, row_top_down);
  if (cell_offsets_.empty()) {
    p.u += physical_index_[channel] / (3.0 * calibration_.screen_w);
    return p;
  }
  // 2.3: the cell pattern uses bottom-up row indices (the parity differs from top-down).
  const int j = calibration_.screen_h - 1 - row_top_down;
  int cell = 0;
  switch (calibration_.cell_pattern_mode) {
    case 1: cell = (x + j) % 2; break;
    case 2: cell = x % 2; break;
    case 3: cell = (j + 2 * (x % 2)) % 4; break;
    case 4: cell = j % 2; break;
    default: cell = 0; break;
  }
  const ScreenUV& d = cell_offsets_[size_t(cell) % cell_offsets_.size()][channel];
  p.u += d.u;
  p.v += d.v;
  return p;
}

double LensModel::phase(ScreenUV p) const {
  return (p.u + p.v * tilt_) * pitch_periods_ - calibration_.center_periods +
         correction_(p.u, p.v);
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
