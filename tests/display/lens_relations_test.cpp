// The physical relations of the display model (display/lens_relations.hpp), each checked
// against its inverse or an independent form of the same relation.
#include "display/lens_relations.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "display/lens_model.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::display {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

ScreenGeometry apw92011_geometry(bool flip_image_x) {
  ScreenGeometry g = read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json")).geometry();
  g.flip_image_x = flip_image_x;
  return g;
}

TEST(ShaderTerms, FollowTheVendorFormula) {
  // pitch' = pitch (W / DPI) cos(atan(1 / slope)), tilt = H / (W slope), written out here with
  // the trigonometry instead of the |s| / sqrt(1 + s^2) form the library uses.
  const ScreenGeometry g = apw92011_geometry(false);
  for (double slope : {-7.521984100341797, 7.521984100341797, -3.0, 12.5}) {
    const ShaderTerms<double> t = shader_terms(g, 50.0693473815918, slope);
    EXPECT_NEAR(t.pitch_periods,
                50.0693473815918 * (g.width_px / g.dpi) * std::cos(std::atan(1.0 / slope)), 1e-9)
        << slope;
    EXPECT_NEAR(t.tilt, g.height_px / (g.width_px * slope), 1e-15) << slope;
  }
}

TEST(ShaderTerms, FlipImageXNegatesOnlyTheTilt) {
  const ShaderTerms<double> plain = shader_terms(apw92011_geometry(false), 50.0, -7.5);
  const ShaderTerms<double> flipped = shader_terms(apw92011_geometry(true), 50.0, -7.5);
  EXPECT_EQ(flipped.pitch_periods, plain.pitch_periods);
  EXPECT_EQ(flipped.tilt, -plain.tilt);
}

TEST(ShaderTerms, InvertToPitchAndSlopeForBothSlopeSignsAndFlips) {
  for (bool flip : {false, true})
    for (double slope : {-7.521984100341797, 7.521984100341797, -3.2, 4.0, -15.0}) {
      SCOPED_TRACE(testing::Message() << "slope " << slope << " flipImageX " << flip);
      const ScreenGeometry g = apw92011_geometry(flip);
      const ShaderTerms<double> t = shader_terms(g, 50.0693473815918, slope);
      const PitchSlope back = pitch_slope_from_shader_terms(g, t.pitch_periods, t.tilt);
      EXPECT_NEAR(back.pitch_lpi, 50.0693473815918, 1e-10);
      EXPECT_NEAR(back.slope, slope, 1e-10 * std::abs(slope));
    }
}

TEST(ShaderTerms, LensModelUsesThem) {
  const DisplayCalibration d = read_visual_json(test::fixture_calibration("LKG-2K-04409.visual.json"));
  const ShaderTerms<double> t = shader_terms(d.geometry(), d.pitch_lpi, d.slope);
  const LensModel lens(d);
  EXPECT_EQ(lens.pitch_periods(), t.pitch_periods);
  EXPECT_EQ(lens.tilt(), t.tilt);
  EXPECT_NEAR(lens.slant_deg(), slant_deg_of_slope(d.slope), 1e-12);
}

TEST(Slant, IsAtanOfOneOverSlopeAndInvertsForBothSigns) {
  EXPECT_NEAR(slant_deg_of_slope(-7.521984100341797), -std::atan(1 / 7.521984100341797) / kDeg, 1e-12);
  EXPECT_NEAR(slant_deg_of_slope(1.0), 45.0, 1e-12);
  for (double slant : {-20.0, -7.57, -0.5, 0.5, 3.0, 7.57, 30.0}) {
    EXPECT_NEAR(slant_deg_of_slope(slope_of_slant_deg(slant)), slant, 1e-12) << slant;
    EXPECT_EQ(slope_of_slant_deg(slant) > 0, slant > 0) << slant;
  }
  // A half-degree slant error is a large slope change (the slope is run over rise).
  const double slope = -7.52;
  // d slope / d slant = -(1 + slope^2) per radian.
  EXPECT_NEAR(slope_of_slant_deg(slant_deg_of_slope(slope) + 0.5) - slope,
              -0.5 * kDeg * (1 + slope * slope), 0.06);
}

TEST(FractionPerTan, IsHalfOverTanOfHalfTheConeAndInverts) {
  EXPECT_NEAR(fraction_per_tan(40.0), 0.5 / std::tan(20.0 * kDeg), 1e-15);
  EXPECT_NEAR(fraction_per_tan(90.0), 0.5, 1e-15);
  for (double cone : {10.0, 35.0, 40.0, 53.5, 89.0, 120.0})
    EXPECT_NEAR(view_cone_from_fraction_per_tan(fraction_per_tan(cone)), cone, 1e-10) << cone;
}

TEST(SeenFraction, SpansTheConeFromEdgeToEdge) {
  for (double cone : {35.0, 40.0, 53.0}) {
    const double t = std::tan(0.5 * cone * kDeg);
    EXPECT_NEAR(seen_fraction_of_tan(0.0, 0.0, 0.2, cone), 0.5, 1e-15);
    EXPECT_NEAR(seen_fraction_of_tan(t, 0.0, 0.2, cone), 1.0, 1e-12);   // right edge of the cone
    EXPECT_NEAR(seen_fraction_of_tan(-t, 0.0, 0.2, cone), 0.0, 1e-12);  // left edge
    // Beyond the edge the neighbouring lens repeats the views.
    EXPECT_GT(seen_fraction_of_tan(1.5 * t, 0.0, 0.2, cone), 1.0);
    EXPECT_NEAR(wrap_fraction(seen_fraction_of_tan(1.5 * t, 0.0, 0.2, cone)), 0.25, 1e-12);
  }
}

TEST(SeenFraction, OfAViewerAndOfADirectionAgree) {
  // A viewer 0.1 m right of a lens, 0.6 m in front, sees what leaves at tan = 0.1 / 0.6.
  // A viewer 0.1 m right and 0.03 m above a lens, 0.6 m in front, sees what leaves at
  // (tan_x, tan_y) = (0.1, 0.03) / 0.6.
  const double lines = -0.13;
  EXPECT_NEAR(seen_fraction(0.1, 0.03, 0.6, lines, 40.0),
              seen_fraction_of_tan(0.1 / 0.6, 0.03 / 0.6, lines, 40.0), 1e-15);
  EXPECT_NEAR(seen_fraction_k(0.1, 0.03, 0.6, lines, fraction_per_tan(40.0)),
              seen_fraction(0.1, 0.03, 0.6, lines, 40.0), 1e-15);
  EXPECT_NEAR(seen_fraction(-0.05, 0.0, 0.45, lines, 50.0),
              0.5 - (0.05 / 0.45) * 0.5 / std::tan(25.0 * kDeg), 1e-15);
}

// Vertical parallax: a slanted lens has power only across its lines. The lines are where the
// LensModel's phase is constant, so the sign of the vertical term is checked against the
// phase itself, with and without flipImageX (which negates the model's tilt, not u).
TEST(SeenFraction, AViewerMovingAlongTheLensLinesSeesNoChange) {
  for (bool flip : {false, true}) {
    SCOPED_TRACE(::testing::Message() << "flipImageX " << flip);
    DisplayCalibration d = read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
    d.flip_image_x = flip;
    const LensModel lens(d);
    EXPECT_NEAR(lens.line_tilt(), (flip ? -1.0 : 1.0) / d.slope, 1e-12);
    // A step along the lens line through (u, v): the phase does not change.
    const double dv = 0.3, du = -dv * lens.tilt();
    ASSERT_NEAR(lens.phase(0.4 + du, 0.2 + dv), lens.phase(0.4, 0.2), 1e-9);
    const double along_x = du * d.width_m(), along_y = dv * d.height_m();
    const double f0 = seen_fraction(0.03, -0.02, 0.5, lens.line_tilt(), d.view_cone_deg);
    EXPECT_NEAR(seen_fraction(0.03 + along_x, -0.02 + along_y, 0.5, lens.line_tilt(), d.view_cone_deg),
                f0, 1e-12);
    // Straight up is not along the lines: it changes f by line_tilt of a horizontal step.
    const double up = seen_fraction(0.03, 0.08, 0.5, lens.line_tilt(), d.view_cone_deg) - f0;
    EXPECT_NEAR(up, 0.1 * lens.line_tilt() * fraction_per_tan(d.view_cone_deg) / 0.5, 1e-12);
    // The Portrait's slope is negative: unflipped, a viewer who rises sees lower fractions.
    ASSERT_LT(d.slope, 0);
    EXPECT_EQ(up > 0, flip);
  }
}

// A camera in front of the centre of a Looking Glass Portrait at 0.5 m: the top and the
// bottom of the screen show views H_m line_tilt k / Cz apart, 0.061 of the cone (about three
// of 48 views), whatever the camera's height.
TEST(SeenFraction, TopAndBottomOfTheScreenDifferByTheLineTilt) {
  const DisplayCalibration d = read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  const LensModel lens(d);
  const double h = d.height_m(), k = fraction_per_tan(d.view_cone_deg);
  for (double cy : {0.0, 0.1, -0.07}) {
    const double top = seen_fraction(0.0, cy - 0.5 * h, 0.5, lens.line_tilt(), d.view_cone_deg);
    const double bottom = seen_fraction(0.0, cy + 0.5 * h, 0.5, lens.line_tilt(), d.view_cone_deg);
    EXPECT_NEAR(top - bottom, -h * (1.0 / d.slope) * k / 0.5, 1e-12) << cy;
    EXPECT_NEAR(top - bottom, 0.0612, 1e-4) << cy;  // slope -7.21, H 0.1606 m, cone 40 deg
  }
  // The centre of the screen seen from 0.1 m above: 0.038 of the cone the other way,
  // 0.1 L k / 0.5 with L = 1 / -7.2115 and k = 1 / (2 tan 20 deg) = 1.3737: -0.0381.
  EXPECT_NEAR(seen_fraction(0.0, 0.1, 0.5, lens.line_tilt(), d.view_cone_deg) - 0.5, -0.0381, 1e-4);
}

TEST(SeenFraction, TanOfSeenFractionInvertsIt) {
  for (double cone : {30.0, 40.0, 60.0})
    for (double f = -0.4; f <= 1.4; f += 0.1) {
      const double tan_theta = tan_of_seen_fraction(f, cone);
      EXPECT_NEAR(seen_fraction_of_tan(tan_theta, 0.0, 0.2, cone), f, 1e-12) << cone << " " << f;
      EXPECT_EQ(tan_theta > 0, f > 0.5 + 1e-12) << cone << " " << f;
    }
}

TEST(WrapFraction, MapsIntoTheUnitInterval) {
  for (double f : {-2.3, -1.0, -0.25, 0.0, 0.4, 0.999, 1.0, 3.75}) {
    const double w = wrap_fraction(f);
    EXPECT_GE(w, 0.0) << f;
    EXPECT_LT(w, 1.0) << f;
    EXPECT_NEAR(w - f, std::round(w - f), 1e-12) << f;
  }
}

TEST(LensContentShift, StaysWithinHalfALensAndRepeatsEveryWholeFraction) {
  for (bool inv : {false, true})
    for (double f = -1.95; f < 2.0; f += 0.0625) {
      const double shift = lens_content_shift(f, inv);
      EXPECT_GE(shift, -0.5) << f;
      EXPECT_LT(shift, 0.5) << f;
      EXPECT_NEAR(lens_content_shift(f + 1.0, inv), shift, 1e-12) << f;
      EXPECT_NEAR(lens_content_shift(f - 2.0, inv), shift, 1e-12) << f;
    }
}

TEST(LensContentShift, IsZeroHeadOnAndMirroredByInvView) {
  EXPECT_NEAR(lens_content_shift(0.5, false), 0.0, 1e-15);
  EXPECT_NEAR(lens_content_shift(0.5, true), 0.0, 1e-15);
  // Without invView the lens shows content at f_seen - 1/2 of a lens; with it, mirrored.
  for (double f : {0.1, 0.3, 0.62, 0.9}) {
    EXPECT_NEAR(lens_content_shift(f, false), f - 0.5, 1e-12) << f;
    EXPECT_NEAR(lens_content_shift(f, true), 0.5 - f, 1e-12) << f;
  }
}

TEST(LensContentShift, JumpsAWholeLensWhereTheSeenFractionWraps) {
  const double eps = 1e-6;
  for (bool inv : {false, true}) {
    const double before = lens_content_shift(1.0 - eps, inv), after = lens_content_shift(1.0 + eps, inv);
    EXPECT_NEAR(std::abs(before - after), 1.0, 1e-5) << inv;
  }
}

}  // namespace
}  // namespace lfd::display
