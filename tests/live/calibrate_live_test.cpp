// The live loop (`lfd calibrate --live`, and with --simulate TRUTH.json): rounds of patterns
// made for the previous estimate, shown and photographed position by position; later rounds
// start closer to the truth. The window and camera versions are in tests/live/window/.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "live/live_calibration.hpp"
#include "live/live_session.hpp"
#include "sim/undescribed_units.hpp"
#include "display/lens_relations.hpp"
#include "sim/synthetic_unit.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {

TEST(CalibrateLive, SimulatedRoundsRefineTheNominalModel) {
  const sim::SyntheticUnit unit = sim::make_synthetic_unit(display::read_visual_json(
      test::fixture_calibration("LKG-PORT-portrait.visual.json")));
  LiveOptions o;
  o.rounds = 2;
  o.positions = 2;  // two distances: the view cone is measured, not assumed
  o.capture_width_px = 480;
  std::vector<sim::CalibrationErrors> errors;
  o.on_round = [&](int, const calib::CalibrationOutcome& out) {
    errors.push_back(sim::compare_with_truth(out.calibration, unit.truth));
  };
  const sim::CalibrationErrors before = sim::compare_with_truth(unit.nominal, unit.truth);
  const calib::CalibrationOutcome out = run_live_calibration_simulated(unit.nominal, unit.truth, o);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_LT(errors[0].phase_rms_periods, 0.2 * before.phase_rms_periods);
  EXPECT_LT(errors[1].phase_rms_periods, 0.2 * before.phase_rms_periods);
  EXPECT_LT(errors[1].pitch_rel, 3e-4);
  EXPECT_LT(errors[1].slant_deg, 0.005);
  EXPECT_TRUE(out.gate_failures.empty());
}

// A panel nobody described, live: round 1 shows the probes and photographs them where the
// camera stands, round 2 the fine set drawn for the lens they showed, from both positions; the
// session's last round solved offline (`lfd calibrate SESSION`) gives the same calibration.
TEST(CalibrateLive, UndescribedPanelProbesThenFineSet) {
  const sim::UndescribedPanel panel = sim::small_undescribed_panel();
  const sim::SyntheticUnit unit = sim::make_synthetic_unit(panel.display);
  const display::DisplayCalibration& t = unit.truth.display;
  LiveOptions o;
  o.rounds = 2;
  o.positions = 2;
  o.capture_width_px = 640;
  o.probes = sim::small_undescribed_probes();
  o.session_dir = std::filesystem::temp_directory_path() /
                  ("lfd_live_undescribed_" + std::to_string(::getpid()));
  std::filesystem::remove_all(o.session_dir);
  std::optional<calib::ProbeRound> probes;
  o.on_probes = [&](const calib::ProbeRound& found) { probes = found; };
  std::vector<int> rounds;
  o.on_round = [&](int round, const calib::CalibrationOutcome&) { rounds.push_back(round); };
  const calib::CalibrationOutcome out =
      run_live_calibration_simulated(o.probes->nominal, unit.truth, o);
  ASSERT_TRUE(probes);
  EXPECT_LT(std::abs(probes->lens.pitch_lpi / t.pitch_lpi - 1), 0.01);
  EXPECT_LT(std::abs(probes->lens.slant_deg - display::slant_deg_of_slope(t.slope)), 0.5);
  EXPECT_EQ(probes->lens.bgr, t.flip_subp);
  EXPECT_EQ(rounds, std::vector<int>{2});  // the probes' round solves nothing
  const sim::CalibrationErrors e = sim::compare_with_truth(out.calibration, unit.truth);
  std::printf("live, undescribed: slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg, phase "
              "%.4f\n",
              e.slant_deg, e.pitch_rel, e.center_periods, e.view_cone_deg, e.phase_rms_periods);
  EXPECT_TRUE(out.gate_failures.empty());
  EXPECT_EQ(out.calibration.display.flip_subp, t.flip_subp);
  EXPECT_LT(e.slant_deg, 0.002);
  EXPECT_LT(e.pitch_rel, 5e-5);
  EXPECT_LT(e.center_periods, 0.01);
  EXPECT_LT(e.view_cone_deg, 1.0);
  EXPECT_LT(e.phase_rms_periods, 0.01);

  // Round 1 holds the probes from one position, round 2 the fine set from both.
  EXPECT_TRUE(sim::read_pattern_set(o.session_dir / "round-1").undescribed);
  EXPECT_TRUE(std::filesystem::exists(o.session_dir / "round-2" / "captures" / "pos2"));
  EXPECT_FALSE(std::filesystem::exists(o.session_dir / "round-1" / "captures" / "pos2"));
  const std::filesystem::path last = capture_folder_of(o.session_dir);
  const sim::PatternSet fine = sim::read_pattern_set(last);
  std::vector<std::string> warnings;
  calib::CalibrateOptions offline;
  offline.camera = sim::CameraIntrinsics::read_yaml(last / "camera.yaml");
  const calib::CalibrationOutcome again =
      calib::calibrate_display(fine, sim::read_captures(last, fine, warnings), offline);
  EXPECT_DOUBLE_EQ(again.calibration.display.pitch_lpi, out.calibration.display.pitch_lpi);
  EXPECT_DOUBLE_EQ(again.calibration.display.center_periods,
                   out.calibration.display.center_periods);
  std::filesystem::remove_all(o.session_dir);
}

// Both devices in one, writing down what the loop asks of them; its "photographs" are grey,
// so calibrate_display stops at the first board.
struct RecordingDevices : PatternDisplay, FrameSource {
  std::vector<std::string> events;
  std::vector<Image8> shown;
  void show(const Image8& pattern) override {
    shown.push_back(pattern);
    events.push_back("show");
  }
  void start_position(int index, int count) override {
    events.push_back("start " + std::to_string(index) + " of " + std::to_string(count));
  }
  void fix_exposure_on_white() override { events.push_back("fix exposure"); }
  cv::Mat capture() override {
    events.push_back("capture");
    return cv::Mat(48, 64, CV_32FC3, cv::Scalar::all(0.5));
  }
};

TEST(CalibrateLive, EachPositionAimsOnTheBoardAndTheSessionFixesExposureOnWhiteOnce) {
  const display::DisplayCalibration d = display::read_visual_json(
      test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  display::Calibration nominal;
  nominal.display = d;
  const sim::PatternSet set = sim::plan_patterns(nominal);
  RecordingDevices devices;
  LiveOptions o;
  o.rounds = 1;
  o.positions = 2;
  o.move_camera = [&](const CameraMove& move) {
    devices.events.push_back("move " + std::to_string(move.position) + " of " +
                             std::to_string(move.count));
  };
  try {
    run_live_calibration(nominal, devices, devices, o);
    FAIL() << "grey photographs have no board";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("round 1, pos1/"), std::string::npos) << e.what();
  }
  std::vector<std::string> expected;
  for (int i = 0; i < 2; ++i) {
    std::vector<const char*> steps = {"show", "move ", "start "};
    if (i == 0) steps.insert(steps.end(), {"show", "fix exposure"});  // once per session
    for (const char* step : steps) {
      std::string event = step;
      if (event == "move ") event += std::to_string(i + 1) + " of 2";
      if (event == "start ") event += std::to_string(i) + " of 2";
      expected.push_back(event);
    }
    for (size_t k = 0; k < set.patterns.size(); ++k) {
      expected.push_back("show");
      expected.push_back("capture");
    }
  }
  EXPECT_EQ(devices.events, expected);
  // What was on screen: the board to aim at, white for the exposure, then the manifest.
  const size_t per_position = set.patterns.size() + 1;
  ASSERT_EQ(devices.shown.size(), 2 * per_position + 1);
  auto same = [](const Image8& a, const Image8& b) { return a.pixels == b.pixels; };
  EXPECT_TRUE(same(devices.shown[0], sim::render_pattern(set, *set.of_kind(sim::PatternKind::kBoard)[0])));
  EXPECT_TRUE(same(devices.shown[1], sim::render_pattern(set, *set.of_kind(sim::PatternKind::kWhite)[0])));
  for (size_t k = 0; k < set.patterns.size(); ++k)
    EXPECT_TRUE(same(devices.shown[per_position + 2 + k], sim::render_pattern(set, set.patterns[k])))
        << set.patterns[k].file;
}

}  // namespace
}  // namespace lfd::live
