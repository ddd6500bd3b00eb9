// Which calibration is served: lfd's calibration.json wins over the factory file of the same
// unit, says so, and files of other units are further displays.
#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "serve/served_display.hpp"
#include "tests/serve/serve_test_support.hpp"

namespace lfd::serve {
namespace {

TEST(ServedDisplays, LfdsCalibrationWinsOverTheFactoryFileOfItsUnit) {
  test::TempDir tmp;
  const auto factory = display::read_calibration(lfd::test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  display::Calibration refined = factory;
  refined.display.pitch_lpi += 0.125;  // what a camera calibration would have measured
  const auto refined_file = tmp.path / "calibration.json";
  display::write_calibration(refined_file, refined, false);
  const auto other_file = lfd::test::fixture_calibration("LKG-2K-04409.visual.json");

  const auto displays = served_displays({refined_file, other_file}, {factory});
  ASSERT_EQ(displays.size(), 2u);
  EXPECT_EQ(displays[0].calibration_source, "lfd calibration.json");
  EXPECT_DOUBLE_EQ(displays[0].calibration.display.pitch_lpi, factory.display.pitch_lpi + 0.125);
  EXPECT_EQ(displays[1].calibration_source, "factory visual.json");
  EXPECT_EQ(displays[1].index, 1);

  const auto factory_only = served_displays({}, {factory});
  ASSERT_EQ(factory_only.size(), 1u);
  EXPECT_EQ(factory_only[0].calibration_source, "factory visual.json");
  EXPECT_DOUBLE_EQ(factory_only[0].calibration.display.pitch_lpi, factory.display.pitch_lpi);
}

}  // namespace
}  // namespace lfd::serve
