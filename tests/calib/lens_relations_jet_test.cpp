// The display relations differentiated with ceres::Jet, as the lens solver uses them
// (calib/display/lens_relations.hpp): the same values as with doubles, and derivatives that
// match finite differences. Here and not in the display tests: lfd_display does not link Ceres.
#include <cmath>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "calib/display/lens_relations.hpp"
#include "calib/display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

using Jet = ceres::Jet<double, 2>;

ScreenGeometry geometry(bool flip_image_x) {
  ScreenGeometry g = read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json")).geometry();
  g.flip_image_x = flip_image_x;
  return g;
}

// Central differences of shader_terms<double> in pitch (index 0) and slope (index 1).
ShaderTerms<double> finite_difference(const ScreenGeometry& g, double pitch, double slope, int index) {
  const double h = index == 0 ? 1e-5 * pitch : 1e-6 * std::abs(slope);
  const double dp = index == 0 ? h : 0, ds = index == 1 ? h : 0;
  const auto plus = shader_terms(g, pitch + dp, slope + ds);
  const auto minus = shader_terms(g, pitch - dp, slope - ds);
  return {(plus.pitch_periods - minus.pitch_periods) / (2 * h), (plus.tilt - minus.tilt) / (2 * h)};
}

TEST(ShaderTermsJet, SameValueAndFiniteDifferenceDerivativesForBothSlopeSigns) {
  for (bool flip : {false, true})
    for (double slope : {-7.521984100341797, 7.521984100341797, -3.5, 11.0}) {
      SCOPED_TRACE(::testing::Message() << "slope " << slope << " flipImageX " << flip);
      const ScreenGeometry g = geometry(flip);
      const double pitch = 50.0693473815918;
      const ShaderTerms<Jet> jet = shader_terms(g, Jet(pitch, 0), Jet(slope, 1));
      const ShaderTerms<double> plain = shader_terms(g, pitch, slope);
      EXPECT_EQ(jet.pitch_periods.a, plain.pitch_periods);
      EXPECT_EQ(jet.tilt.a, plain.tilt);
      for (int i = 0; i < 2; ++i) {
        const ShaderTerms<double> fd = finite_difference(g, pitch, slope, i);
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
    const Jet f = seen_fraction(Jet(0.08), Jet(0.55), Jet(cone, 0));
    EXPECT_EQ(f.a, seen_fraction(0.08, 0.55, cone));
    const double h = 1e-5;
    const double fd = (seen_fraction(0.08, 0.55, cone + h) - seen_fraction(0.08, 0.55, cone - h)) / (2 * h);
    EXPECT_NEAR(f.v[0], fd, 1e-7) << cone;
    EXPECT_LT(f.v[0], 0.0);  // a wider cone: the same direction is a smaller step off centre
  }
}

}  // namespace
}  // namespace lfd::calib
