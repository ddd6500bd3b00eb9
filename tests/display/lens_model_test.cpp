#include "display/lens_model.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::display {
namespace {

DisplayCalibration load(const char* name) {
  return read_visual_json(test::fixture_calibration(name));
}

double frac(double x) { return x - std::floor(x); }

// Published processed shader values (sgumhold/cgv libs/holo_disp/glsl/holo_disp.glfs;
// docs/display-model.md "The test vector").
TEST(LensModel, ReproducesThePublishedShaderUniforms) {
  const LensModel gen2(load("LKG-APW92011.visual.json"));
  EXPECT_NEAR(gen2.pitch_periods(), 673.46088569750157, 1e-9);
  EXPECT_NEAR(gen2.tilt(), -0.074780801514116493, 1e-15);
  const LensModel gen1(load("LKG-2K-04409.visual.json"));
  // Not published; the same formulas in double precision: pitch' = 47.56401443481445 (2560 / 338)
  // cos(atan(1 / -5.48)) = 354.39586, tilt = 1600 / (2560 x -5.48) = -0.11405109.
  EXPECT_NEAR(gen1.pitch_periods(), 354.39586, 1e-5);
  EXPECT_NEAR(gen1.tilt(), -0.11405109, 1e-8);
}

TEST(LensModel, ClassicSubpixelPhaseMatchesTheVendorFormula) {
  const DisplayCalibration c = load("LKG-2K-04409.visual.json");
  const LensModel lens(c);
  const double P = lens.pitch_periods(), T = lens.tilt(), s = 1.0 / (3.0 * c.screen_w);
  for (int x : {0, 17, 1280, 2559})
    for (int row : {0, 5, 800, 1599})
      for (int ch = 0; ch < 3; ++ch) {
        // The vendor phase (docs/display-model.md "Phase and view") with j bottom-up:
        // v = (j + 0.5)/H, j = H - 1 - row.
        const double u = (x + 0.5) / c.screen_w, v = (c.screen_h - 1 - row + 0.5) / c.screen_h;
        const double a = (u + ch * s + v * T) * P - c.center_periods;
        const double f = std::clamp(1.0 - frac(a), 1e-5, 0.999999);  // invView = 1
        EXPECT_NEAR(lens.subpixel_view_fraction(x, row, ch), f, 1e-9);
      }
}

TEST(LensModel, FlipSubpSwapsRedAndBluePositions) {
  DisplayCalibration c = load("LKG-2K-04409.visual.json");
  const LensModel rgb(c);
  c.flip_subp = true;
  const LensModel bgr(c);
  EXPECT_DOUBLE_EQ(bgr.subpixel_uv(10, 10, 0).u, rgb.subpixel_uv(10, 10, 2).u);
  EXPECT_DOUBLE_EQ(bgr.subpixel_uv(10, 10, 2).u, rgb.subpixel_uv(10, 10, 0).u);
  EXPECT_DOUBLE_EQ(bgr.subpixel_uv(10, 10, 1).u, rgb.subpixel_uv(10, 10, 1).u);
}

TEST(LensModel, FlipImageXNegatesTilt) {
  DisplayCalibration c = load("LKG-2K-04409.visual.json");
  const double t = LensModel(c).tilt();
  c.flip_image_x = true;
  EXPECT_DOUBLE_EQ(LensModel(c).tilt(), -t);
}

TEST(LensModel, Gen3CellsUseBottomUpRowParity) {
  const DisplayCalibration c = load("template-16in-portrait-gen3.visual.json");
  const LensModel lens(c);
  // Mode 4 = row parity of the bottom-up row j. The bottom image row (row H-1) has j = 0:
  // cell 0, red at (-0.25, -0.31) pixels from the pixel centre.
  const int bottom = c.screen_h - 1;
  const ScreenUV centre = lens.pixel_uv(7, bottom);
  const ScreenUV red = lens.subpixel_uv(7, bottom, 0);
  EXPECT_NEAR((red.u - centre.u) * c.screen_w, -0.25, 1e-9);
  EXPECT_NEAR((red.v - centre.v) * c.screen_h, -0.31, 1e-9);
  const ScreenUV red1 = lens.subpixel_uv(7, bottom - 1, 0);  // j = 1: cell 1
  EXPECT_NEAR((red1.u - lens.pixel_uv(7, bottom - 1).u) * c.screen_w, 0.25, 1e-9);
  const ScreenUV blue = lens.subpixel_uv(7, bottom, 2);
  EXPECT_NEAR((blue.u - centre.u) * c.screen_w, 0.25, 1e-9);
  EXPECT_NEAR((blue.v - centre.v) * c.screen_h, 0.0, 1e-9);
}

TEST(LensModel, CorrectionFieldShiftsThePhase) {
  const DisplayCalibration c = load("LKG-APW92011.visual.json");
  std::vector<double> coeffs(5 * 4, 0.125);  // a constant B-spline is that constant
  const LensModel plain(c), corrected(c, CorrectionField(5, 4, coeffs));
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.77, 1.0})
      EXPECT_NEAR(corrected.phase(u, v) - plain.phase(u, v), 0.125, 1e-12);
}

// The row form the direct pass and the interlacer use is subpixel_view_fraction itself, bit for
// bit, on every subpixel of whole panels: classic RGB and BGR, every Gen3 cell pattern, a
// correction field, invView either way.
TEST(LensModel, RowViewFractionsEqualSubpixelViewFractionBitForBit) {
  std::vector<std::pair<std::string, LensModel>> lenses;
  for (const char* name : {"LKG-2K-04409.visual.json", "LKG-PORT-portrait.visual.json"}) {
    DisplayCalibration c = load(name);
    lenses.emplace_back(name, LensModel(c));
    c.flip_subp = true;
    c.inv_view = !c.inv_view;
    lenses.emplace_back(std::string(name) + " bgr", LensModel(c));
  }
  for (int mode = 0; mode <= 4; ++mode) {
    DisplayCalibration c = load("template-16in-portrait-gen3.visual.json");
    c.cell_pattern_mode = mode;
    lenses.emplace_back("gen3 mode " + std::to_string(mode), LensModel(c));
  }
  std::vector<double> coeffs(6 * 5);
  for (size_t i = 0; i < coeffs.size(); ++i) coeffs[i] = 0.05 * std::sin(double(i));
  lenses.emplace_back("corrected", LensModel(load("LKG-APW92011.visual.json"), CorrectionField(6, 5, coeffs)));
  for (const auto& [what, lens] : lenses) {
    const DisplayCalibration& c = lens.calibration();
    std::vector<double> row(3 * size_t(c.screen_w));
    size_t compared = 0, unequal = 0;
    for (int r = 0; r < c.screen_h; r += (c.screen_h > 1000 ? 7 : 1)) {
      lens.row_view_fractions(r, row.data());
      for (int x = 0; x < c.screen_w; ++x)
        for (int ch = 0; ch < 3; ++ch) {
          ++compared;
          if (row[3 * size_t(x) + size_t(ch)] != lens.subpixel_view_fraction(x, r, ch)) ++unequal;
        }
    }
    EXPECT_GT(compared, 100000u) << what;
    EXPECT_EQ(unequal, 0u) << what;
  }
}

TEST(LensModel, PhaseForFractionInvertsViewFraction) {
  for (bool inv : {true, false}) {
    DisplayCalibration c = load("LKG-APW92011.visual.json");
    c.inv_view = inv;
    const LensModel lens(c);
    for (double f : {0.01, 0.3, 0.5, 0.97}) {
      const double a = lens.phase_for_fraction(f, 12.0);
      EXPECT_GE(a, 12.0);
      EXPECT_LT(a, 13.0);
      EXPECT_NEAR(lens.view_fraction(a), f, 1e-12);
    }
  }
}

TEST(LensModel, ViewIndexClampsToTheLastView) {
  EXPECT_EQ(LensModel::view_index(0.999999, 45), 44);
  EXPECT_EQ(LensModel::view_index(1.0, 45), 44);
  EXPECT_EQ(LensModel::view_index(1e-5, 45), 0);
  EXPECT_EQ(LensModel::view_index(0.5, 45), 22);
}

}  // namespace
}  // namespace lfd::display
