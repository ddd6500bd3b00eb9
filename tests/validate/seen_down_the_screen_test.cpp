// What one eye sees from the bottom to the top of a Looking Glass Portrait (vertical parallax,
// docs/display-model.md "What a viewer sees"): measured through the simulator's optics, it follows
// seen_fraction().
#include "validate/seen_down_the_screen.hpp"

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::validate {
namespace {

display::Calibration portrait() {
  display::Calibration c;
  c.display = display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  return c;
}

TEST(SeenDownTheScreen, AnEyeAboveTheCentreSeesOtherViewsAtTheTopThanAtTheBottom) {
  const display::Calibration truth = portrait();
  const auto rows = seen_down_the_screen(truth, Eigen::Vector3d(0.0, 0.1, 0.5), 5);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_LT(rows.front().y_m, 0.0);
  EXPECT_GT(rows.back().y_m, 0.0);
  for (const auto& r : rows) EXPECT_NEAR(fraction_difference(r.measured, r.predicted), 0.0, 0.005) << r.y_m << " seen " << r.measured << " predicted " << r.predicted;
  // 90 % of the height: 0.9 x 0.0612 of the cone, about 2.6 of 48 views.
  const double top_bottom = fraction_difference(rows.back().measured, rows.front().measured);
  EXPECT_NEAR(top_bottom, 0.9 * 0.0612, 0.004);
}

TEST(SeenDownTheScreen, AnEyeBehindThePanelIsInputError) {
  EXPECT_THROW(seen_down_the_screen(portrait(), Eigen::Vector3d(0.0, 0.1, -0.5)), InputError);
  EXPECT_THROW(seen_down_the_screen(portrait(), Eigen::Vector3d(0.0, 0.1, 0.5), 1), InputError);
}

}  // namespace
}  // namespace lfd::validate
