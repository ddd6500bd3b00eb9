#pragma once
// Displays and panels shared by the simulator tests.
#include <complex>
#include <numbers>
#include <string>

#include "display/calibration_file.hpp"
#include "display/lens_model.hpp"
#include "util/image.hpp"

namespace lfd::sim::testing {

// The real 16" Gen2 unit LKG-APW92011 (docs/display-model.md "The test vector"), embedded so the
// tests need no shared data.
inline display::DisplayCalibration apw92011() {
  return display::parse_calibration(
             R"({"configVersion":"3.0","serial":"LKG-APW92011","pitch":{"value":50.0693473815918},
             "slope":{"value":-7.521984100341797},"center":{"value":0.07635253667831421},
             "fringe":{"value":0.0},"viewCone":{"value":40.0},"invView":{"value":1.0},
             "verticalAngle":{"value":0.0},"DPI":{"value":283.0},"screenW":{"value":3840.0},
             "screenH":{"value":2160.0},"flipImageX":{"value":0.0},"flipImageY":{"value":0.0},
             "flipSubp":{"value":0.0}})",
             "LKG-APW92011.visual.json")
      .display;
}

// A small display with the same optics per lens (17 subpixels per lens, same slant) so
// full captures stay cheap in tests: 384 x 216 pixels at a tenth of the DPI.
inline display::DisplayCalibration small_display() {
  display::DisplayCalibration c = apw92011();
  c.screen_w = 384;
  c.screen_h = 216;
  c.dpi = 28.3;
  c.pitch_lpi = 5.00693473815918;
  return c;
}

// The 16" Portrait Gen3 factory template (LKG-Toolkit HardCodedLKGDeviceTemplates.cs:
// CellPatternMode 4, two subpixel cells) at a tenth of the resolution and DPI: same optics per
// lens, small panel.
inline display::DisplayCalibration small_gen3_portrait() {
  return display::parse_calibration(
             R"({"configVersion":"3.0","serial":"LKG-H-template","pitch":{"value":4.472},
             "slope":{"value":-7.45},"center":{"value":0.0},"viewCone":{"value":50.0},
             "invView":{"value":1.0},"DPI":{"value":28.3},"screenW":{"value":216.0},
             "screenH":{"value":384.0},"CellPatternMode":{"value":4.0},"subpixelCells":[
             {"ROffsetX":-0.25,"ROffsetY":-0.31,"GOffsetX":-0.25,"GOffsetY":0.28,"BOffsetX":0.25,"BOffsetY":0.0},
             {"ROffsetX":0.25,"ROffsetY":-0.31,"GOffsetX":0.25,"GOffsetY":0.28,"BOffsetX":-0.25,"BOffsetY":0.0}]})",
             "template-16in-portrait-gen3.visual.json")
      .display;
}

// Every subpixel shows its own view index as grey level index / (views - 1).
inline ImageF view_index_panel(const display::LensModel& lens, int views) {
  const auto& c = lens.calibration();
  ImageF panel(c.screen_w, c.screen_h, 3);
  for (int row = 0; row < c.screen_h; ++row)
    for (int x = 0; x < c.screen_w; ++x)
      for (int ch = 0; ch < 3; ++ch)
        panel.at(x, row, ch) =
            float(display::LensModel::view_index(lens.subpixel_view_fraction(x, row, ch), views)) /
            float(views - 1);
  return panel;
}

// The view fraction seen around photo pixel (x, y), in turns: the phasor of the photos of the
// cosine and sine fraction panels (display/fraction_panel.hpp), less half the white panel's photo,
// summed over the 13 x 9 pixels around it.
inline double seen_fraction_around(const ImageF& photo_cos, const ImageF& photo_sin, const ImageF& photo_white, int x,
                                   int y) {
  std::complex<double> z = 0;
  for (int py = y - 4; py <= y + 4; ++py)
    for (int px = x - 6; px <= x + 6; ++px)
      for (int ch = 0; ch < 3; ++ch) {
        const double w = 0.5 * photo_white.at(px, py, ch);
        z += std::complex<double>(photo_cos.at(px, py, ch) - w, photo_sin.at(px, py, ch) - w);
      }
  return std::arg(z) / (2.0 * std::numbers::pi);
}

}  // namespace lfd::sim::testing
