// The colour-order check (calib/decoding/colour_order.hpp, docs/calibration.md 3.7): each colour
// channel decodes its own phase; a subpixel layout that is not the panel's (RGB taken for BGR, a
// Gen3 cell table on a striped panel) leaves a constant offset per channel of known size, and the
// check names the layout the photos favour. Phase photos of the small bench display from one camera
// with the bench's effects (noise, blur, vignetting, distortion, glare), registered by projection.
#include "calib/decoding/colour_order.hpp"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sim/capture_io.hpp"
#include "display/lens_model.hpp"
#include "sim/synthetic_unit.hpp"
#include "tests/sim/simulator_test_support.hpp"

namespace lfd::calib {
namespace {

Registration register_by_projection(const sim::PatternSet& set, const sim::PhysicalCamera& camera) {
  BoardDetection board;
  board.image_size = {camera.intrinsics().width, camera.intrinsics().height};
  for (size_t id = 0; id < set.board.corners_px.size(); ++id) {
    const display::ScreenUV uv = panel_px_to_uv(set.nominal.display, set.board.corners_px[id]);
    Eigen::Vector2d px;
    if (!camera.project(uv_to_display_m(set.nominal.display, uv), px)) continue;
    board.ids.push_back(int(id));
    board.image_px.emplace_back(float(px.x()), float(px.y()));
  }
  return Registration(board, set, camera.intrinsics());
}

struct Bench {
  double exposure_drift = 0.0;
  double colour_crosstalk = 0.0;
};

// The phase photos of a panel whose true layout is `truth`'s, showing patterns drawn for
// `drawn`, decoded as `lfd calibrate` decodes them.
DecodedPhase photograph(const display::DisplayCalibration& truth, const display::DisplayCalibration& drawn,
                        const Bench& bench = {}) {
  display::Calibration nominal;
  nominal.display = drawn;
  sim::PatternOptions po;
  po.fringes = false;
  const sim::PatternSet set = sim::plan_patterns(nominal, po);
  sim::CaptureRig rig = sim::make_capture_rig(truth, 320, 1);
  rig.effects.exposure_drift = bench.exposure_drift;
  rig.effects.colour_crosstalk = bench.colour_crosstalk;
  const sim::DisplaySimulator sim{display::LensModel(truth)};
  const sim::PhysicalCamera camera(rig.intrinsics, rig.poses[0]);
  double exposure = rig.effects.exposure;
  for (const auto* p : set.of_kind(sim::PatternKind::kWhite))
    exposure = sim::exposure_on_white(sim, to_float(sim::render_pattern(set, *p)), camera, rig.effects);
  std::vector<cv::Mat> captures;
  for (const auto* p : set.of_kind(sim::PatternKind::kPhase)) {
    sim::CaptureEffects e = sim::photo_effects(rig, 0, size_t(p->index));
    e.exposure = exposure;
    captures.push_back(sim::to_mat(sim.capture(to_float(sim::render_pattern(set, *p)), camera, e)));
  }
  return decode_phase(captures, register_by_projection(set, camera), set);
}

ColourOrderCheck check(const display::DisplayCalibration& drawn, const DecodedPhase& phase,
                       std::optional<SubpixelLayout> given = {}, bool estimate = false) {
  ColourOrderOptions o;
  o.estimate = estimate;
  const ColourOrderCheck c =
      compare_subpixel_layouts(drawn, given.value_or(SubpixelLayout::of(drawn)), {&phase}, o);
  std::printf("%s\n", to_json(c).dump().c_str());
  return c;
}

display::DisplayCalibration bgr(display::DisplayCalibration d) {
  d.flip_subp = true;
  return d;
}

// R and B trade places: each moves 2/3 pixel, pitch / DPI lens periods per pixel across the
// lines (the slant's cosine in pitch'), against the phase under invView.
TEST(ColourOrder, PredictsTwoThirdsOfAPixelForSwappedRedAndBlue) {
  const display::DisplayCalibration rgb = sim::testing::small_display();
  const display::LensModel lens(rgb);
  const double per_px = lens.pitch_periods() / rgb.screen_w;
  const auto o = predicted_channel_offsets(rgb, {false, true});
  EXPECT_NEAR(o[0], 2.0 / 3.0 * per_px, 1e-9);  // inv_view: + for a drawn position to the left
  EXPECT_NEAR(o[1], 0.0, 1e-12);
  EXPECT_NEAR(o[2], -2.0 / 3.0 * per_px, 1e-9);
  EXPECT_GT(o[0] - o[2], 0.1);  // 0.118 lens periods on 17-subpixel lenses
  for (double x : predicted_channel_offsets(rgb, {false, false})) EXPECT_NEAR(x, 0.0, 1e-12);
}

TEST(ColourOrder, BgrPanelPhotographedWithRgbPatternsIsRefusedNamingFlipSubp1) {
  const display::DisplayCalibration rgb = sim::testing::small_display();
  const ColourOrderCheck c = check(rgb, photograph(bgr(rgb), rgb));
  ASSERT_TRUE(c.refused());
  EXPECT_EQ(c.best, (SubpixelLayout{false, true}));
  EXPECT_NE(c.finding.find("flipSubp is 0, the photos say 1"), std::string::npos) << c.finding;
  EXPECT_NE(c.finding.find("--flip-subp 1"), std::string::npos) << c.finding;
  // The measured offsets are the predicted ones (R - G +0.059, B - G -0.059 periods).
  EXPECT_LT(c.candidates.back().miss_periods, 0.01);
}

TEST(ColourOrder, RgbPanelDescribedAsBgrIsRefusedNamingFlipSubp0) {
  const display::DisplayCalibration rgb = sim::testing::small_display();
  const ColourOrderCheck c = check(bgr(rgb), photograph(rgb, bgr(rgb)));
  ASSERT_TRUE(c.refused());
  EXPECT_EQ(c.best, (SubpixelLayout{false, false}));
  EXPECT_NE(c.finding.find("flipSubp is 1, the photos say 0: rerun with --flip-subp 0"),
            std::string::npos)
      << c.finding;
}

TEST(ColourOrder, RightLayoutPassesUnderExposureDriftAndCameraNoise) {
  const display::DisplayCalibration rgb = sim::testing::small_display();
  Bench bench;
  bench.exposure_drift = 0.03;
  const ColourOrderCheck c = check(rgb, photograph(rgb, rgb, bench));
  EXPECT_FALSE(c.photos_disagree) << c.finding;
  EXPECT_EQ(c.best, (SubpixelLayout{false, false}));
  EXPECT_LT(std::abs(c.measured_periods[0]), 0.01);
  EXPECT_LT(std::abs(c.measured_periods[1]), 0.01);
}

TEST(ColourOrder, GivenLayoutOverridesThePatternsAndEstimationAdoptsTheBest) {
  // Patterns drawn for RGB on a BGR panel, the user says BGR: accepted, and the samples are
  // re-decoded for BGR. Says RGB with estimation: BGR is adopted, not refused.
  const display::DisplayCalibration rgb = sim::testing::small_display();
  const DecodedPhase phase = photograph(bgr(rgb), rgb);
  const ColourOrderCheck told = check(rgb, phase, SubpixelLayout{false, true});
  EXPECT_FALSE(told.photos_disagree) << told.finding;
  EXPECT_EQ(told.adopted, (SubpixelLayout{false, true}));
  const ColourOrderCheck estimated = check(rgb, phase, {}, true);
  EXPECT_TRUE(estimated.photos_disagree);
  EXPECT_FALSE(estimated.refused());
  EXPECT_EQ(estimated.adopted, (SubpixelLayout{false, true}));
  EXPECT_EQ(estimated.adopted.apply(rgb).flip_subp, true);
}

TEST(ColourOrder, CameraColourCrosstalkDilutesButKeepsTheVerdict) {
  const display::DisplayCalibration rgb = sim::testing::small_display();
  for (double x : {0.05, 0.10, 0.15}) {
    Bench bench;
    bench.colour_crosstalk = x;
    const ColourOrderCheck c = check(rgb, photograph(bgr(rgb), rgb, bench));
    const auto predicted = c.candidates.back().predicted_periods;  // flipSubp 1
    const double ratio = (c.measured_periods[0] - c.measured_periods[1]) /
                         (predicted[0] - predicted[1]);
    std::printf("crosstalk %.2f: R - B measured / predicted %.3f\n", x, ratio);
    // Each channel keeps 1 - 2x of its own light and takes x of each other: about 1 - 3x.
    EXPECT_NEAR(ratio, 1 - 3 * x, 0.06) << x;
    EXPECT_EQ(c.best, (SubpixelLayout{false, true})) << x;
    if (x <= 0.10) {
      EXPECT_TRUE(c.refused()) << x;
    } else {  // diluted past the refusal margin: said, not refused
      EXPECT_FALSE(c.refused()) << x;
      EXPECT_NE(c.finding.find("lean toward flipSubp 1"), std::string::npos) << c.finding;
    }
  }
}

TEST(ColourOrder, StripedPanelDescribedWithGen3CellsIsRefused) {
  const display::DisplayCalibration cells = sim::testing::small_gen3_portrait();
  const ColourOrderCheck c = check(cells, photograph(SubpixelLayout{false, false}.apply(cells), cells));
  ASSERT_TRUE(c.refused());
  EXPECT_EQ(c.best, (SubpixelLayout{false, false}));
  EXPECT_NE(c.finding.find("--flip-subp 0"), std::string::npos) << c.finding;
}

TEST(ColourOrder, Gen3CellsThatAreRightPass) {
  const display::DisplayCalibration cells = sim::testing::small_gen3_portrait();
  const ColourOrderCheck c = check(cells, photograph(cells, cells));
  EXPECT_FALSE(c.photos_disagree) << c.finding;
  EXPECT_EQ(c.best, (SubpixelLayout{true, false}));
}

}  // namespace
}  // namespace lfd::calib
