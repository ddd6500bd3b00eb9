// The plan of what calibrate_display solves (calib/solve_plan.hpp; docs/calibration.md, "What
// is solved: the plan"), on every path: a described unit and a panel nobody described, one or
// two solves, a view cone and a cover given or not, a known or self-calibrated camera, offline
// and live, and the combinations that are refused before any work.
#include "calib/solve_plan.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "calib/undescribed.hpp"
#include "display/cover_layer.hpp"
#include "display/visual_json.hpp"
#include "sim/camera_model.hpp"
#include "sim/patterns.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

// A described unit: the Portrait, with its family's cover (2 cm of acrylic, a tolerance).
display::Calibration described_unit() {
  display::Calibration c;
  c.display = display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  c.display.cover = display::cover_layer_for_family(c.display).cover;
  return c;
}

// The fine set's description of a panel nobody described, as the probes give it (the
// Portrait's screen; `cover`: what `lfd patterns --screen` was given, none by default).
display::Calibration undescribed_panel(display::CoverLayer cover = {0.0, 1.49}) {
  sim::PatternSet coarse;
  coarse.nominal = described_unit();
  ProbeLensEstimate lens;
  lens.pitch_lpi = 43.6;
  lens.slope = 5.96;
  UndescribedAssumptions assumptions;
  assumptions.cover = cover;
  assumptions.cover_given = cover.present();
  return description_from_probes(coarse, lens, assumptions);
}

sim::CameraIntrinsics known_camera() {
  sim::CameraIntrinsics k;
  k.width = 1920;
  k.height = 1080;
  return k;
}

std::string refusal(const PlanInputs& inputs, const CalibrateOptions& options) {
  try {
    plan_solves(inputs, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool same_cover(const display::CoverLayer& a, const display::CoverLayer& b) {
  return a.thickness_m == b.thickness_m && a.refractive_index == b.refractive_index;
}

TEST(SolvePlan, DescribedUnitIsSolvedOnceWithItsFamilysCoverPrior) {
  const display::Calibration unit = described_unit();
  CalibrateOptions options;
  options.camera = known_camera();
  const SolvePlan plan = plan_solves({unit, 2}, options);
  ASSERT_EQ(plan.solves.size(), 1u);
  EXPECT_EQ(plan.solves[0].role, SolveRole::kOnly);
  EXPECT_FALSE(plan.solves[0].reason.empty());
  EXPECT_FALSE(plan.undescribed);
  // The cover resolved to the family's estimate, with its tolerance as the prior's sigma;
  // the description already holds its mean, so registration starts from the description.
  const display::CoverDefault family = display::cover_layer_for_family(unit.display);
  ASSERT_TRUE(plan.options.cover);
  EXPECT_TRUE(same_cover(plan.options.cover->cover, family.cover));
  EXPECT_EQ(plan.options.cover->sigma_m, family.thickness_sigma_m);
  EXPECT_GT(plan.options.cover->sigma_m, 0);
  EXPECT_TRUE(same_cover(plan.nominal.display.cover, unit.display.cover));
  EXPECT_EQ(plan.nominal.display.view_cone_deg, unit.display.view_cone_deg);
  EXPECT_FALSE(plan.nominal.view_cone_measured_deg);
  EXPECT_FALSE(plan.options.colour_order.estimate);  // the description's order is checked
  EXPECT_TRUE(plan.options.camera);
}

TEST(SolvePlan, DescriptionWithoutACoverIsSolvedAsABarePanel) {
  display::Calibration unit = described_unit();
  unit.display.cover = {};
  const SolvePlan plan = plan_solves({unit, 2}, CalibrateOptions{});
  ASSERT_TRUE(plan.options.cover);
  EXPECT_FALSE(plan.options.cover->cover.present());
  EXPECT_EQ(plan.options.cover->sigma_m, 0);  // held: its error is not in the sigmas
  EXPECT_FALSE(plan.nominal.display.cover.present());
}

TEST(SolvePlan, GivenViewConeBecomesTheMeasuredOneWithTheNominalKept) {
  const display::Calibration unit = described_unit();
  CalibrateOptions options;
  options.view_cone_deg = 35.5;
  const SolvePlan plan = plan_solves({unit, 1}, options);
  EXPECT_EQ(plan.nominal.display.view_cone_deg, 35.5);
  ASSERT_TRUE(plan.nominal.view_cone_measured_deg);
  EXPECT_EQ(*plan.nominal.view_cone_measured_deg, 35.5);
  ASSERT_TRUE(plan.nominal.view_cone_nominal_deg);
  EXPECT_EQ(*plan.nominal.view_cone_nominal_deg, unit.display.view_cone_deg);
  EXPECT_FALSE(plan.options.view_cone_deg);  // folded into the description, not given twice
  ASSERT_EQ(plan.solves.size(), 1u);
  EXPECT_EQ(plan.solves[0].role, SolveRole::kOnly);
}

TEST(SolvePlan, AnEarlierNominalConeIsKeptWhenTheConeIsGivenAgain) {
  display::Calibration unit = described_unit();
  unit.view_cone_nominal_deg = 40.0;
  unit.view_cone_measured_deg = unit.display.view_cone_deg = 33.0;
  CalibrateOptions options;
  options.view_cone_deg = 34.0;
  const SolvePlan plan = plan_solves({unit, 2}, options);
  EXPECT_EQ(*plan.nominal.view_cone_nominal_deg, 40.0);
  EXPECT_EQ(*plan.nominal.view_cone_measured_deg, 34.0);
}

TEST(SolvePlan, GivenCoverReplacesTheDescriptionsAndRegistrationAssumesItsMean) {
  const display::Calibration unit = described_unit();
  CalibrateOptions options;
  options.cover = CoverGiven::range(0.004, 0.010, 1.5, "between 4 and 10 mm");
  const SolvePlan plan = plan_solves({unit, 2}, options);
  EXPECT_DOUBLE_EQ(plan.nominal.display.cover.thickness_m, 0.007);
  EXPECT_EQ(plan.nominal.display.cover.refractive_index, 1.5);
  ASSERT_TRUE(plan.options.cover);
  EXPECT_EQ(plan.options.cover->said, "between 4 and 10 mm");
  EXPECT_DOUBLE_EQ(plan.options.cover->sigma_m, 0.006 / std::sqrt(12.0));
  ASSERT_EQ(plan.solves.size(), 1u);
}

TEST(SolvePlan, UndescribedPanelWithNoCoverSaidIsUnknownAndSolvedTwice) {
  const display::Calibration panel = undescribed_panel();
  ASSERT_TRUE(from_probes(panel));
  const SolvePlan plan = plan_solves({panel, 2}, CalibrateOptions{});
  EXPECT_TRUE(plan.undescribed);
  // Nobody said what covers the lenses: unknown (0-25 mm), not none; registration assumes the
  // prior's mean.
  ASSERT_TRUE(plan.options.cover);
  EXPECT_DOUBLE_EQ(plan.options.cover->cover.thickness_m, CoverGiven::kUnknownMaxM / 2);
  EXPECT_DOUBLE_EQ(plan.options.cover->sigma_m, CoverGiven::kUnknownMaxM / std::sqrt(12.0));
  EXPECT_TRUE(same_cover(plan.nominal.display.cover, plan.options.cover->cover));
  // The subpixel order the probes read is checked by the photos, and replaced if they say so.
  EXPECT_TRUE(plan.options.colour_order.estimate);
  // The cone is assumed: solved with the assumption, then registered and solved again with the
  // cone the first solve measured.
  ASSERT_EQ(plan.solves.size(), 2u);
  EXPECT_EQ(plan.solves[0].role, SolveRole::kConeAssumed);
  EXPECT_EQ(plan.solves[1].role, SolveRole::kConeMeasured);
  EXPECT_NE(plan.solves[0].reason, plan.solves[1].reason);
  EXPECT_EQ(plan.nominal.display.view_cone_deg, UndescribedAssumptions{}.view_cone_deg);
  EXPECT_FALSE(plan.nominal.view_cone_measured_deg);
}

TEST(SolvePlan, UndescribedPanelKeepsTheCoverGivenToThePatternsHeld) {
  const display::Calibration panel = undescribed_panel({0.003, 1.49});
  const SolvePlan plan = plan_solves({panel, 3}, CalibrateOptions{});
  ASSERT_TRUE(plan.options.cover);
  EXPECT_TRUE(same_cover(plan.options.cover->cover, {0.003, 1.49}));
  EXPECT_EQ(plan.options.cover->sigma_m, 0);  // no family to take a tolerance from: held
  EXPECT_TRUE(same_cover(plan.nominal.display.cover, {0.003, 1.49}));
  EXPECT_EQ(plan.solves.size(), 2u);
}

TEST(SolvePlan, UndescribedPanelTakesTheCoverGivenToCalibrate) {
  const display::Calibration panel = undescribed_panel();
  CalibrateOptions options;
  options.cover = CoverGiven::range(0.0, 0.002, 1.49, "between 0 and 2 mm");
  const SolvePlan plan = plan_solves({panel, 2}, options);
  EXPECT_EQ(plan.options.cover->said, "between 0 and 2 mm");
  EXPECT_DOUBLE_EQ(plan.nominal.display.cover.thickness_m, 0.001);
}

TEST(SolvePlan, UndescribedPanelIsSolvedOnceWhenItsConeCannotBeOrNeedNotBeMeasured) {
  const display::Calibration panel = undescribed_panel();
  {
    SCOPED_TRACE("one position: nothing to measure the cone with");
    const SolvePlan plan = plan_solves({panel, 1}, CalibrateOptions{});
    ASSERT_EQ(plan.solves.size(), 1u);
    EXPECT_EQ(plan.solves[0].role, SolveRole::kOnly);
    EXPECT_TRUE(plan.options.colour_order.estimate);
  }
  {
    SCOPED_TRACE("the cone given");
    CalibrateOptions options;
    options.view_cone_deg = 26.0;
    const SolvePlan plan = plan_solves({panel, 3}, options);
    ASSERT_EQ(plan.solves.size(), 1u);
    EXPECT_EQ(plan.nominal.display.view_cone_deg, 26.0);
  }
  {
    SCOPED_TRACE("the cone not fitted");
    CalibrateOptions options;
    options.solver.fit_view_cone = false;
    EXPECT_EQ(plan_solves({panel, 3}, options).solves.size(), 1u);
  }
}

TEST(SolvePlan, KnownAndSelfCalibratedCamerasGetTheSamePlan) {
  for (const display::Calibration& nominal : {described_unit(), undescribed_panel()}) {
    CalibrateOptions known;
    known.camera = known_camera();
    const SolvePlan with = plan_solves({nominal, 3}, known);
    const SolvePlan without = plan_solves({nominal, 3}, CalibrateOptions{});
    EXPECT_TRUE(with.options.camera);
    EXPECT_FALSE(without.options.camera);  // choose_camera self-calibrates it
    ASSERT_EQ(with.solves.size(), without.solves.size());
    for (size_t i = 0; i < with.solves.size(); ++i)
      EXPECT_EQ(with.solves[i].role, without.solves[i].role);
    EXPECT_EQ(with.options.cover->said, without.options.cover->said);
  }
}

// The old controller rewrote its options and called itself until nothing changed: a plan's
// own result must plan to itself (same description, cover and solves).
TEST(SolvePlan, APlansResultPlansToItself) {
  CalibrateOptions cone;
  cone.view_cone_deg = 38.0;
  for (const auto& [nominal, options] :
       {std::pair{described_unit(), CalibrateOptions{}}, std::pair{described_unit(), cone},
        std::pair{undescribed_panel(), CalibrateOptions{}}, std::pair{undescribed_panel(), cone}}) {
    const SolvePlan once = plan_solves({nominal, 2}, options);
    const SolvePlan twice = plan_solves({once.nominal, 2}, once.options);
    EXPECT_EQ(to_json(twice.nominal).dump(), to_json(once.nominal).dump());
    EXPECT_EQ(twice.options.cover->said, once.options.cover->said);
    EXPECT_EQ(twice.options.cover->sigma_m, once.options.cover->sigma_m);
    EXPECT_EQ(twice.options.colour_order.estimate, once.options.colour_order.estimate);
    EXPECT_EQ(twice.solves.size(), once.solves.size());
  }
}

TEST(SolvePlan, LiveRefusesOnePositionThatCannotMeasureTheConeBeforeAnythingIsShown) {
  const display::Calibration unit = described_unit();
  CalibrateOptions options;
  options.camera = known_camera();
  const std::string message = refusal({unit, 1, /*live=*/true}, options);
  EXPECT_NE(message.find("--positions 1"), std::string::npos) << message;
  EXPECT_NE(message.find("--view-cone"), std::string::npos) << message;
  // Offline the same photos are solved and the cone gate reports it (with the figures).
  EXPECT_EQ(refusal({unit, 1}, options), "");
  // Live, what makes one position work: the cone given, or measured before, or more positions.
  CalibrateOptions cone = options;
  cone.view_cone_deg = 40.0;
  EXPECT_EQ(refusal({unit, 1, true}, cone), "");
  display::Calibration measured = unit;
  measured.view_cone_measured_deg = measured.display.view_cone_deg;
  EXPECT_EQ(refusal({measured, 1, true}, options), "");
  EXPECT_EQ(refusal({unit, 2, true}, options), "");
}

TEST(SolvePlan, LivePlansLikeOfflineOtherwise) {
  const display::Calibration panel = undescribed_panel();
  const SolvePlan live = plan_solves({panel, 3, true}, CalibrateOptions{});
  const SolvePlan offline = plan_solves({panel, 3, false}, CalibrateOptions{});
  ASSERT_EQ(live.solves.size(), 2u);
  EXPECT_EQ(live.solves.size(), offline.solves.size());
  EXPECT_EQ(to_json(live.nominal).dump(), to_json(offline.nominal).dump());
}

TEST(SolvePlan, CombinationsThatCannotWorkAreRefusedBeforeAnyWork) {
  const display::Calibration unit = described_unit();
  EXPECT_NE(refusal({unit, 0}, CalibrateOptions{}).find("no camera positions"), std::string::npos);
  CalibrateOptions rig;
  rig.known_camera_positions_m = {Eigen::Vector3d(0, 0, 0.6), Eigen::Vector3d(0.1, 0, 0.8)};
  EXPECT_NE(refusal({unit, 3}, rig).find("known_camera_positions_m: 2 given for 3 positions"),
            std::string::npos);
  EXPECT_EQ(refusal({unit, 2}, rig), "");
  CalibrateOptions cone;
  cone.view_cone_deg = 200.0;
  EXPECT_NE(refusal({unit, 2}, cone).find("view_cone_deg"), std::string::npos);
  CalibrateOptions cover;
  cover.cover = CoverGiven::range(0.0, 0.01, 0.5, "glass of index 0.5");
  EXPECT_NE(refusal({unit, 2}, cover).find("cover.refractive_index"), std::string::npos);
}

}  // namespace
}  // namespace lfd::calib
