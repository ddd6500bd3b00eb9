#pragma once
// The one lens model everything uses (docs/display-model.md "Phase and view" and
// "Vendor interlacing rules"):
//   A(u, v) = (u + v * tilt) * pitch' - center + w(u, v)
// with pitch' and tilt from shader_terms() (lens_relations.hpp),
// per-channel subpixel positions (classic 1/3-pixel stride, BGR via flipSubp, or Gen3 cells),
// view fraction f = 1 - frac(A) (invView) or frac(A), clamped to [1e-5, 0.999999], and the view
// index floor(f * V). The interlacer, the simulator, the pattern generator and the solver all
// call this class, so they cannot disagree.
#include <array>

#include "display/correction_field.hpp"
#include "display/display_calibration.hpp"

namespace lfd::display {

struct ScreenUV {
  double u = 0;  // 0 at the left edge, 1 at the right
  double v = 0;  // 0 at the bottom edge, 1 at the top (Looking Glass / GL convention)
};

class LensModel {
 public:
  explicit LensModel(const DisplayCalibration& calibration,
                     CorrectionField correction = CorrectionField());

  const DisplayCalibration& calibration() const { return calibration_; }
  const CorrectionField& correction() const { return correction_; }

  // Lens periods across the screen width, measured horizontally (P of the shaders).
  double pitch_periods() const { return pitch_periods_; }
  // Phase change per unit v relative to u (T of the shaders).
  double tilt() const { return tilt_; }
  // The lens lines run along x + y * line_tilt() = const (pixels, y up): tilt * W / H.
  double line_tilt() const { return display::line_tilt(calibration_.geometry(), tilt_); }
  // Subpixels per lens period along a pixel row.
  double subpixels_per_lens() const { return 3.0 * calibration_.screen_w / pitch_periods_; }
  // Lens slant from vertical in degrees (signed as the slope).
  double slant_deg() const;

  // Screen coordinates of the centre of pixel (x, row) with row 0 at the top of the image.
  // Inline: the direct pass and the interlacer call it per pixel.
  ScreenUV pixel_uv(int x, int row_top_down) const {
    return {(x + 0.5) / calibration_.screen_w, 1.0 - (row_top_down + 0.5) / calibration_.screen_h};
  }
  // Where channel c (0 R, 1 G, 2 B) of that pixel physically emits.
  ScreenUV subpixel_uv(int x, int row_top_down, int channel) const;

  // Lens phase A(u, v) in lens periods (unwrapped; its floor is the lens index).
  double phase(ScreenUV p) const;
  double phase(double u, double v) const { return phase(ScreenUV{u, v}); }
  // The view fraction a subpixel with phase A shows (invView and the vendor clamp applied).
  double view_fraction(double phase) const;
  // The view fraction of channel c of pixel (x, row).
  double subpixel_view_fraction(int x, int row_top_down, int channel) const {
    return view_fraction(phase(subpixel_uv(x, row_top_down, channel)));
  }
  // subpixel_view_fraction of every subpixel of panel row `row_top_down`, bit for bit:
  // out[3 x + c] for x < screen_w, with the row's and each column's part of subpixel_uv computed
  // once (the direct panel pass and the interlacer go a row at a time; docs/performance.md
  // "Where the direct pass's time went"). `out` holds 3 screen_w values.
  void row_view_fractions(int row_top_down, double* out) const;
  // The phase within lens m that shows view fraction f (inverse of view_fraction).
  double phase_for_fraction(double f, double lens_index) const;
  // floor(f * views), clamped to [0, views - 1].
  static int view_index(double fraction, int views);

 private:
  DisplayCalibration calibration_;
  CorrectionField correction_;
  double pitch_periods_ = 0;
  double tilt_ = 0;
  // The Gen3 cell of pixel x in bottom-up row j (docs/display-model.md "Vendor interlacing rules").
  int cell_index(int x, int j) const;

  std::array<int, 3> physical_index_{0, 1, 2};  // flipSubp: R and B swap positions
  std::vector<std::array<ScreenUV, 3>> cell_offsets_;  // Gen3 cells, normalised once
};

}  // namespace lfd::display
