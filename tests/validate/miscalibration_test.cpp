#include "validate/miscalibration.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"

namespace lfd::validate {
namespace {

display::Calibration unit() {
  display::Calibration c;
  c.display = display::parse_visual_json(
      R"({"pitch":{"value":50.0693473815918},"slope":{"value":-7.521984100341797},"center":{"value":0.076},)"
      R"("DPI":{"value":283},"screenW":{"value":3840},"screenH":{"value":2160}})",
      "unit");
  c.correction = display::CorrectionField(4, 4, std::vector<double>(16, 0.05));
  return c;
}

double slant_deg(const display::Calibration& c) {
  return std::atan(1.0 / c.display.slope) * 180.0 / std::numbers::pi;
}

TEST(Miscalibration, RotatesTheLensAngleByExactlyTheGivenDegrees) {
  for (double d : {0.01, -0.5}) {
    const auto c = apply(unit(), Miscalibration{.slant_deg = d});
    EXPECT_NEAR(slant_deg(c) - slant_deg(unit()), d, 1e-12);
    EXPECT_EQ(c.display.pitch_lpi, unit().display.pitch_lpi);
  }
}

TEST(Miscalibration, ScalesPitchShiftsCenterAndDropsTheCorrection) {
  const auto c = apply(unit(), Miscalibration{.pitch_relative = 2e-5, .center_periods = 0.25,
                                              .drop_correction = true});
  EXPECT_NEAR(c.display.pitch_lpi, 50.0693473815918 * (1 + 2e-5), 1e-12);
  EXPECT_NEAR(c.display.center_periods, 0.326, 1e-12);
  EXPECT_TRUE(c.correction.empty());
  EXPECT_EQ(Miscalibration{}.describe(), "none");
  EXPECT_NE(Miscalibration{.slant_deg = 0.01}.describe().find("slant"), std::string::npos);
}

}  // namespace
}  // namespace lfd::validate
