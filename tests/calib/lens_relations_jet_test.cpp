// The display relations differentiated with ceres::Jet, as the lens solver uses them
// (display/lens_relations.hpp): the same values as with doubles, and derivatives that
// match finite differences. Here and not in the display tests: lfd_display does not link Ceres.
#include <cmath>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "display/lens_relations.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

using Jet = ceres::Jet<double, 2>;

display::ScreenGeometry geometry(bool flip_image_x) {
  display::ScreenGeometry g = display::read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json")).geometry();
  g.flip_image_x = flip_image_x;
  return g;
}

// Central differences of shader_terms<double> in pitch (index 0) and slope (index 1).
display::ShaderTerms<double> finite_difference(const display::ScreenGeometry& g, double pitch, double slope, int index) {
  const double h = index == 0 ? 1e-5 * pitch : 1e-6 * std::abs(slope);
  const double dp = index == 0 ? h : 0, ds = index == 1 ? h : 0;
  const auto plus = display::shader_terms(g, pitch + dp, slope + ds);
  const auto minus = display::shader_terms(g, pitch - dp, slope - ds);
  return {(plus.pitch_periods - minus.pitch_periods) / (2 * h), (plus.tilt - minus.tilt) / (2 * h)};
}

TEST(ShaderTermsJet, SameValueAndFiniteDifferenceDerivativesForBothSlopeSigns) {
  for (bool flip : {false, true})
    for (double slope : {-7.521984100341797, 7.521984100341797, -3.5, 11.0}) {
      SCOPED_TRACE(::testing::Message() << "slope " << slope << " flipImageX " << flip);
      const display::ScreenGeometry g = geometry(flip);
      const double pitch = 50.0693473815918;
      const display::ShaderTerms<Jet> jet = display::shader_terms(g, Jet(pitch, 0), Jet(slope, 1));
      const display::ShaderTerms<double> plain = display::shader_terms(g, pitch, slope);
      EXPECT_EQ(jet.pitch_periods.a, plain.pitch_periods);
      EXPECT_EQ(jet.tilt.a, plain.tilt);
      for (int i = 0; i < 2; ++i) {
        const display::ShaderTerms<double> fd = finite_difference(g, pitch, slope, i);
        EXPECT_NEAR(jet.pitch_periods.v[i], fd.pitch_periods, 1e-6 * std::abs(fd.pitch_periods) + 1e-9)
            << "d pitch' / d " << (i ? "slope" : "pitch");
        EXPECT_NEAR(jet.tilt.v[i], fd.tilt, 1e-6 * std::abs(fd.tilt) + 1e-12)
            << "d tilt / d " << (i ? "slope" : "pitch");
      }
      // pitch' is proportional to the pitch; the tilt does not depend on it.
      EXPECT_NEAR(jet.pitch_periods.v[0], plain.pitch_periods / pitch, 1e-9);
      EXPECT_EQ(jet.tilt.v[0], 0.0);
    }
}

TEST(SeenFractionJet, DerivativeInTheConeMatchesAFiniteDifference) {
  for (double cone : {35.0, 40.0, 50.0}) {
    const Jet f = display::seen_fraction(Jet(0.08), Jet(0.0), Jet(0.55), Jet(0.15), Jet(cone, 0));
    EXPECT_EQ(f.a, display::seen_fraction(0.08, 0.0, 0.55, 0.15, cone));
    const double h = 1e-5;
    const double fd = (display::seen_fraction(0.08, 0.0, 0.55, 0.15, cone + h) -
                       display::seen_fraction(0.08, 0.0, 0.55, 0.15, cone - h)) / (2 * h);
    EXPECT_NEAR(f.v[0], fd, 1e-7) << cone;
    EXPECT_LT(f.v[0], 0.0);  // a wider cone: the same direction is a smaller step off centre
  }
}

// The solver differentiates f_seen in the camera's height and, through the tilt, the slope.
TEST(SeenFractionJet, DerivativesInHeightAndLineTiltMatchFiniteDifferences) {
  using Jet4 = ceres::Jet<double, 4>;
  const double dx = 0.05, dy = -0.06, dz = 0.52, lines = -0.1387, cone = 40.0;
  const Jet4 f = display::seen_fraction(Jet4(dx, 0), Jet4(dy, 1), Jet4(dz, 2), Jet4(lines, 3), Jet4(cone));
  EXPECT_EQ(f.a, display::seen_fraction(dx, dy, dz, lines, cone));
  const double h = 1e-6;
  auto at = [&](int i, double step) {
    double x[4] = {dx, dy, dz, lines};
    x[i] += step;
    return display::seen_fraction(x[0], x[1], x[2], x[3], cone);
  };
  for (int i = 0; i < 4; ++i) {
    const double fd = (at(i, h) - at(i, -h)) / (2 * h);
    EXPECT_NEAR(f.v[i], fd, 1e-6 * std::abs(fd) + 1e-8) << "parameter " << i;
  }
  // d f / d Cy = line_tilt d f / d Cx: the vertical offset is worth line_tilt of a horizontal one.
  EXPECT_NEAR(f.v[1], lines * f.v[0], 1e-12);
}

}  // namespace
}  // namespace lfd::calib
