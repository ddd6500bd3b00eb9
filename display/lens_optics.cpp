#include "display/lens_optics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/error.hpp"

namespace lfd::display {

void check_panel_size(const LensModel& lens, const ImageF& panel) {
  const auto& c = lens.calibration();
  if (panel.width != c.screen_w || panel.height != c.screen_h)
    throw_input_error("panel: size: {}x{}, but the display calibration needs {}x{} (screenW x screenH)",
                      panel.width, panel.height, c.screen_w, c.screen_h);
  if (panel.channels != 1 && panel.channels != 3 && panel.channels != 4)
    throw_input_error("panel: channels: {} (expected 1, 3 or 4)", panel.channels);
}

PhaseKernel LensOptics::make_kernel(const LensModel& lens, double psf_sigma_phase) {
  // sigma_u = sigma_A / pitch': the phase advances pitch' lens periods per unit u.
  return PhaseKernel(1.0 / (3.0 * lens.calibration().screen_w),
                     std::max(0.0, psf_sigma_phase) / lens.pitch_periods());
}

LensOptics::LensOptics(const LensModel& lens, const ImageF& panel, const PhaseKernel& kernel)
    : lens_(lens), panel_(panel), kernel_(kernel) {
  const auto& c = lens.calibration();
  view_cone_deg_ = c.view_cone_deg;
  cover_ = c.cover;
  pitch_periods_ = lens.pitch_periods();
  line_tilt_ = lens.line_tilt();
  has_correction_ = !lens.correction().empty();
  has_cells_ = c.has_cells();
  width_ = c.screen_w;
  height_ = c.screen_h;
  for (int ch = 0; ch < 3; ++ch)
    channel_offset_u_[ch] = lens.subpixel_uv(0, 0, ch).u - lens.pixel_uv(0, 0).u;
}

double LensOptics::seen_fraction(double tan_x, double tan_y) const {
  return wrap_fraction(display::seen_fraction_of_tan(tan_x, tan_y, line_tilt_, view_cone_deg_));
}

double LensOptics::seen_u(double u, double v, double fraction) const {
  // Through lens m = floor(A(P)) the viewer sees the phase that shows `fraction`. A is linear
  // in u up to the smooth correction w, so one step is exact without w; with it the step
  // contracts the error by |dw/du| / pitch' (~1e-3) per iteration.
  const double a_p = lens_.phase(u, v);
  const double target = lens_.phase_for_fraction(fraction, std::floor(a_p));
  double u_q = u + (target - a_p) / pitch_periods_;
  if (has_correction_)
    for (int i = 0; i < 4; ++i) {
      const double error = target - lens_.phase(u_q, v);
      u_q += error / pitch_periods_;
      if (std::abs(error) < 1e-12) break;
    }
  return u_q;
}

float LensOptics::channel_emission(double u_q, double v, int channel) const {
  const int pc = panel_.channels == 1 ? 0 : channel;
  const double reach = kernel_.reach_u();
  if (!has_cells_) {
    // Classic stripes: channel c of pixel x emits at (x + 0.5) / W + offset_c on row `row`.
    const int row = std::clamp(int(std::floor((1.0 - v) * height_)), 0, height_ - 1);
    // Q in pixel units relative to the channel-c emitter centres (emitter x sits at x).
    const double q_px = (u_q - channel_offset_u_[channel]) * width_ - 0.5;
    const double reach_px = reach * width_;
    const int x_lo = std::max(0, int(std::ceil(q_px - reach_px)));
    const int x_hi = std::min(width_ - 1, int(std::floor(q_px + reach_px)));
    const float* line = panel_.row(row);
    const double inv_width = 1.0 / width_;
    double sum = 0.0;
    for (int x = x_lo; x <= x_hi; ++x)
      sum += kernel_((q_px - x) * inv_width) * line[x * panel_.channels + pc];
    return float(3.0 * sum);
  }
  const int x_lo = std::max(0, int(std::floor((u_q - reach) * width_ - 1.5)));
  const int x_hi = std::min(width_ - 1, int(std::ceil((u_q + reach) * width_ + 0.5)));
  if (x_lo > x_hi) return 0.0f;
  // The pixel row holding v (row 0 at the top).
  const int row0 = std::clamp(int(std::floor((1.0 - v) * height_)), 0, height_ - 1);
  double sum = 0.0;
  for (int x = x_lo; x <= x_hi; ++x) {
    int row = row0;
    ScreenUV s = lens_.subpixel_uv(x, row, channel);
    if (has_cells_) {
      // Gen3 emitters sit off the pixel centre vertically too: take the row whose channel-c
      // emitter is nearest to the seen point's height.
      for (int r : {row0 - 1, row0 + 1}) {
        if (r < 0 || r >= height_) continue;
        const ScreenUV t = lens_.subpixel_uv(x, r, channel);
        if (std::abs(t.v - v) < std::abs(s.v - v)) {
          s = t;
          row = r;
        }
      }
    }
    const double w = kernel_(u_q - s.u);
    if (w > 0.0) sum += w * panel_.at(x, row, pc);
  }
  // A channel's boxes cover a third of the row: a uniform white panel averages to 1.
  return float(3.0 * sum);
}

std::array<float, 3> LensOptics::seen(double u, double v, double tan_x, double tan_y) const {
  if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return {0.0f, 0.0f, 0.0f};
  const double u_q = seen_u(u, v, seen_fraction(tan_x, tan_y));
  return {channel_emission(u_q, v, 0), channel_emission(u_q, v, 1), channel_emission(u_q, v, 2)};
}

std::array<float, 3> LensOptics::seen_toward(double u, double v, double dx, double dy,
                                             double dz) const {
  if (!(dz > cover_.thickness_m)) return {0.0f, 0.0f, 0.0f};  // the lenses emit toward z > 0
  const double d = cover_seen_distance(dx, dy, dz, cover_);
  return seen(u, v, dx / d, dy / d);
}

}  // namespace lfd::display
