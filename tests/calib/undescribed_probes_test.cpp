// A panel nobody described (docs/calibration.md, "A panel nobody described"): the probe
// gratings find its pitch and slant, with the slant's sign, from one position's photos, and
// what is not such a photo is refused in one line naming what is missing.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "calib/calibrate.hpp"
#include "calib/lens_probes.hpp"
#include "calib/undescribed.hpp"
#include "display/lens_model.hpp"
#include "sim/synthetic_unit.hpp"
#include "sim/undescribed_units.hpp"
#include "tests/calib/cached_captures.hpp"
#include "util/error.hpp"

#include <opencv2/core.hpp>

namespace lfd::calib {
namespace {

struct ProbeFixture {
  sim::SyntheticUnit unit;
  sim::PatternSet set;
  sim::CaptureRig rig;
  std::vector<sim::PositionCaptures> captures;
};

const ProbeFixture& probe_fixture() {
  static const ProbeFixture f = [] {
    ProbeFixture f;
    const sim::UndescribedPanel panel = sim::small_undescribed_panel();
    f.unit = sim::make_synthetic_unit(panel.display);
    f.set = sim::small_undescribed_probes();
    f.rig = sim::make_capture_rig(f.unit.truth.display, 640, 1, false);
    f.captures = test::cached_captures("undescribed_probes_small_v1", [&] {
      return sim::simulate_captures(f.set, f.unit.truth, f.rig);
    });
    return f;
  }();
  return f;
}

TEST(UndescribedProbes, PlanCoversTheRangeWithFewProbes) {
  const sim::PatternSet& set = probe_fixture().set;
  EXPECT_TRUE(set.undescribed);
  EXPECT_TRUE(set.of_kind(sim::PatternKind::kPhase).empty());
  EXPECT_EQ(set.of_kind(sim::PatternKind::kProbe).size(), set.probes.size() * 3);
  EXPECT_LE(set.probes.size(), 12u);
  // The default ranges (10-150 LPI, +-30 degrees) on the bench's tablet: every lens in reach.
  const auto probes = sim::plan_lens_probes(1920, 1200, 224.2);
  std::printf("10\" tablet, default ranges: %zu probes\n", probes.size());
  for (double lpi : {10.0, 40.0, 90.0, 150.0})
    for (double slant : {-30.0, -8.0, 0.0, 17.0, 30.0}) {
      const double width_in = 1920 / 224.2;
      const double p = lpi * width_in * std::cos(slant * std::numbers::pi / 180);
      const double pt = p * 1200.0 / 1920.0 * std::tan(slant * std::numbers::pi / 180);
      bool covered = false;
      for (const auto& q : probes)
        covered |= std::abs(q.fu - p) <= q.window_u && std::abs(q.fv - pt) <= q.window_v;
      EXPECT_TRUE(covered) << lpi << " lpi, " << slant << " deg";
    }
}

TEST(UndescribedProbes, FindPitchSlantAndItsSignFromOnePosition) {
  const ProbeFixture& f = probe_fixture();
  const ProbeLensEstimate e = measure_lens_from_probes(f.set, f.captures[0]);
  const display::DisplayCalibration& t = f.unit.truth.display;
  const display::LensModel truth(t);
  std::printf("subpixel order %s (true %s)\n", e.bgr ? "BGR" : "RGB", t.flip_subp ? "BGR" : "RGB");
  std::printf("probe %d: moire (%.2f, %.2f) strength %.0f; pitch %.3f lpi (true %.3f), slant "
              "%.3f deg (true %.3f), P' %.2f (true %.2f)\n",
              e.chosen.probe, e.chosen.moire_u, e.chosen.moire_v, e.chosen.strength, e.pitch_lpi,
              t.pitch_lpi, e.slant_deg, display::slant_deg_of_slope(t.slope), e.pitch_periods,
              truth.pitch_periods());
  for (const auto& p : e.peaks)
    std::printf("  probe %d (%.1f, %.1f): moire (%.2f, %.2f) strength %.1f, P' %.1f, P'T %.1f\n",
                p.probe, f.set.probes[size_t(p.probe)].fu, f.set.probes[size_t(p.probe)].fv,
                p.moire_u, p.moire_v, p.strength, p.pitch_periods, p.tilt_periods);
  // Inside what the described pipeline's coarse start takes: 1 % pitch, 0.5 degree slant.
  EXPECT_LT(std::abs(e.pitch_lpi / t.pitch_lpi - 1), 0.01);
  EXPECT_LT(std::abs(e.slant_deg - display::slant_deg_of_slope(t.slope)), 0.5);
  EXPECT_EQ(e.bgr, t.flip_subp);
}

// Garbage: a board photo that shows no board.
TEST(UndescribedProbes, GarbageIsRefusedNamingThePhoto) {
  sim::PositionCaptures garbage = probe_fixture().captures[0];
  cv::Mat& board = garbage.images.at("00_board");
  board = cv::Mat(board.size(), board.type());  // new pixels: the fixture's are shared
  cv::randu(board, 0.0f, 1.0f);
  try {
    (void)measure_lens_from_probes(probe_fixture().set, garbage);
    FAIL() << "garbage accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("00_board.png: no board"), std::string::npos) << e.what();
  }
}

// Photos of another screen: the probes show no lens (a screen without the sheet, or another
// monitor showing something still), or another pattern's corner markers.
TEST(UndescribedProbes, PhotosOfAnotherScreenAreRefused) {
  const ProbeFixture& f = probe_fixture();
  // A screen that showed the same grey in every probe photo (not this screen's patterns), with
  // its own sensor noise in each.
  const cv::Mat& board = f.captures[0].images.at("00_board");
  const cv::Mat frozen(board.size(), board.type(), cv::Scalar::all(0.3));
  sim::PositionCaptures still = f.captures[0];
  cv::RNG rng(7);
  for (auto& [stem, image] : still.images)
    if (stem.find("_probe_") != std::string::npos) {
      cv::Mat noise(frozen.size(), frozen.type());
      rng.fill(noise, cv::RNG::NORMAL, 0.0, 0.01);
      const cv::Mat photo = frozen + noise;
      image = photo;  // a new header: the fixture's pixels are shared
    }
  try {
    (void)measure_lens_from_probes(f.set, still);
    FAIL() << "still photos accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no lens in the probe photos"), std::string::npos)
        << e.what();
  }
  sim::PositionCaptures swapped = f.captures[0];
  const auto probes = f.set.of_kind(sim::PatternKind::kProbe);
  auto stem = [](const sim::PatternInfo* p) { return std::filesystem::path(p->file).stem().string(); };
  swapped.images.at(stem(probes[0])) = f.captures[0].images.at(stem(probes[4]));
  try {
    (void)measure_lens_from_probes(f.set, swapped);
    FAIL() << "a photo of another pattern accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("other corner markers"), std::string::npos) << e.what();
  }
}

// End to end: the lens the probes found draws the fine set, which the described pipeline
// solves with its gates and sigmas (camera given, 2 positions at 1.0x and 1.3x distance: the
// small camera does not find the board of this small screen from 1.6x).
TEST(UndescribedCalibrate, SmallBgrPanelSolvedEndToEnd) {
  const ProbeFixture& f = probe_fixture();
  const ProbeLensEstimate lens = measure_lens_from_probes(f.set, f.captures[0]);
  const display::Calibration description = description_from_probes(f.set, lens, {});
  const sim::PatternSet fine = plan_fine_patterns(f.set, description);
  const sim::CaptureRig rig = sim::make_capture_rig(f.unit.truth.display, 640, 2, false);
  const auto captures = test::cached_captures("undescribed_fine_small_v2", [&] {
    return sim::simulate_captures(fine, f.unit.truth, rig);
  });
  CalibrateOptions options;
  options.camera = rig.intrinsics;  // the colour-order estimate is on for a set from the probes
  const CalibrationOutcome out = calibrate_display(fine, captures, options);
  const sim::CalibrationErrors e = sim::compare_with_truth(out.calibration, f.unit.truth);
  std::printf("slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg, warp %.4f, phase %.4f\n",
              e.slant_deg, e.pitch_rel, e.center_periods, e.view_cone_deg,
              e.correction_rms_periods, e.phase_rms_periods);
  for (const auto& w : out.warnings) std::printf("warning: %s\n", w.c_str());
  for (const auto& g : out.gate_failures) std::printf("gate: %s\n", g.c_str());
  // Registration (the board's pose, anchored by the corner markers at the screen's corners,
  // then the fringes) through the cover's prior mean (unknown: 12.5 mm; this sheet is bare),
  // then the solve, which moves each camera with the cover it finds: every camera where the
  // rig put it.
  for (size_t i = 0; i < out.positions.size(); ++i) {
    const double registered = 1000 * (out.positions[i].camera_m - rig.poses[i].position_m).norm();
    const double mm = 1000 * (out.positions[i].camera_refined_m - rig.poses[i].position_m).norm();
    std::printf("%s registered %.2f mm, solved %.2f mm from the truth\n",
                out.positions[i].name.c_str(), registered, mm);
    EXPECT_LT(mm, 3.0) << out.positions[i].name;
  }
  // Registered and solved again with the cone the first solve measured; the assumption stays
  // the cone's nominal.
  EXPECT_EQ(out.calibration.view_cone_nominal_deg, UndescribedAssumptions{}.view_cone_deg);
  EXPECT_TRUE(out.gate_failures.empty());
  EXPECT_TRUE(out.calibration.display.flip_subp);
  EXPECT_LT(e.slant_deg, 0.002);
  EXPECT_LT(e.pitch_rel, 5e-5);
  EXPECT_LT(e.center_periods, 0.01);
  EXPECT_LT(e.view_cone_deg, 1.0);
  EXPECT_LT(e.phase_rms_periods, 0.01);
  const auto& sigma = out.calibration.uncertainty;
  EXPECT_LT(e.slant_deg, 4 * sigma.at("slant_deg"));
  EXPECT_LT(e.center_periods, 4 * sigma.at("center_periods"));
  EXPECT_LT(e.view_cone_deg, 4 * sigma.at("view_cone_deg"));
  EXPECT_LT(e.pitch_rel, 4 * sigma.at("pitch_lpi") / out.calibration.display.pitch_lpi);
}

}  // namespace
}  // namespace lfd::calib
