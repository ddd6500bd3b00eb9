// A live run saves its photographs as capture folders as they are taken
// (live/live_session.hpp): interrupted, it resumes with only the positions not yet
// complete; `lfd calibrate` on the folder re-solves it to the live result; the camera's
// settings are locked once per run. One simulated session (interrupted, then resumed) backs
// every test here.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "live/live_calibration.hpp"
#include "live/live_session.hpp"
#include "live/simulated_live_devices.hpp"
#include "sim/synthetic_unit.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {
namespace fs = std::filesystem;

// The simulated camera, writing down where it photographs and how often it locks settings.
struct PositionLog : FrameSource {
  explicit PositionLog(SimulatedCamera& camera) : camera(camera) {}
  void start_position(int index, int count) override {
    started.push_back(index);
    camera.start_position(index, count);
  }
  void fix_exposure_on_white() override { camera.fix_exposure_on_white(); }
  cv::Mat capture() override { return camera.capture(); }
  SimulatedCamera& camera;
  std::vector<int> started;
};

struct Interrupted {};

struct RunLog {
  std::vector<int> started;  // positions photographed (start_position), in order
  int locks = 0;
  std::vector<std::string> moves;  // "round R pos P"
  std::optional<calib::CalibrationOutcome> outcome;
};

class LiveSessionTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    unit_ = new sim::SyntheticUnit(sim::make_synthetic_unit(
        display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"))));
    dir_ = fs::temp_directory_path() / ("lfd-live-session-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    first_ = new RunLog(run(/*interrupt_at_round_2_position_2=*/true));
  }
  // The resumed run, made when a test first asks for it: CTest runs each test in a process of its
  // own, and the tests that read only the interrupted run need not pay for the resumed one.
  static const RunLog& resumed() {
    if (!resumed_) resumed_ = new RunLog(run(false));
    return *resumed_;
  }
  static void TearDownTestSuite() {
    fs::remove_all(dir_);
    delete first_;
    delete resumed_;
    resumed_ = nullptr;
    delete unit_;
  }

  static LiveOptions options() {
    LiveOptions o;
    o.rounds = 2;
    o.positions = 2;
    o.capture_width_px = 480;
    o.session_dir = dir_;
    return o;
  }

  static RunLog run(bool interrupt) {
    LiveOptions o = options();
    sim::CaptureRig rig = sim::make_capture_rig(unit_->truth.display, o.capture_width_px, o.positions);
    o.calibrate.camera = rig.intrinsics;
    RememberedPattern screen;
    SimulatedCamera camera(unit_->truth, rig, [&screen] { return screen.pattern(); });
    PositionLog log(camera);
    RunLog out;
    o.move_camera = [&](const CameraMove& m) {
      out.moves.push_back("round " + std::to_string(m.round) + " pos" + std::to_string(m.position));
      if (interrupt && m.round == 2 && m.position == 2) throw Interrupted{};
    };
    try {
      out.outcome = run_live_calibration(unit_->nominal, screen, log, o);
    } catch (const Interrupted&) {
    }
    out.started = log.started;
    out.locks = camera.settings_locks();
    return out;
  }

  static sim::SyntheticUnit* unit_;
  static fs::path dir_;
  static RunLog* first_;
  static RunLog* resumed_;
};
sim::SyntheticUnit* LiveSessionTest::unit_ = nullptr;
fs::path LiveSessionTest::dir_;
RunLog* LiveSessionTest::first_ = nullptr;
RunLog* LiveSessionTest::resumed_ = nullptr;

TEST_F(LiveSessionTest, WithIntrinsicsGivenEachPositionIsAskedForOnce) {
  // Round 1 at position 1 only, round 2 from there: the camera never returns anywhere.
  EXPECT_EQ(first_->moves, (std::vector<std::string>{"round 1 pos1", "round 2 pos2"}));
  EXPECT_EQ(first_->started, (std::vector<int>{0, 0}));
  EXPECT_FALSE(first_->outcome.has_value());
}

TEST_F(LiveSessionTest, ResumingPhotographsOnlyThePositionsNotComplete) {
  EXPECT_EQ(resumed().started, (std::vector<int>{1}));
  EXPECT_EQ(resumed().moves, (std::vector<std::string>{"round 2 pos2"}));
  ASSERT_TRUE(resumed().outcome.has_value());
  EXPECT_TRUE(resumed().outcome->gate_failures.empty());
  ASSERT_EQ(resumed().outcome->positions.size(), 2u);
}

TEST_F(LiveSessionTest, SettingsAreLockedOncePerRunNotPerPositionOrRound) {
  EXPECT_EQ(first_->locks, 1);    // two positions photographed in two rounds
  EXPECT_EQ(resumed().locks, 1);  // a new run locks again, once
}

TEST_F(LiveSessionTest, TheSavedFolderSolvedOfflineGivesTheLiveResult) {
  ASSERT_TRUE(resumed().outcome.has_value());
  const fs::path folder = capture_folder_of(dir_);
  EXPECT_EQ(folder, dir_ / "round-2");
  const sim::PatternSet set = sim::read_pattern_set(folder);
  std::vector<std::string> warnings;
  const auto captures = sim::read_captures(folder, set, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  calib::CalibrateOptions co;
  co.camera = sim::CameraIntrinsics::read_yaml(folder / "camera.yaml");
  const calib::CalibrationOutcome offline = calib::calibrate_display(set, captures, co);
  const display::DisplayCalibration& live = resumed().outcome->calibration.display;
  const display::DisplayCalibration& off = offline.calibration.display;
  EXPECT_NEAR(off.pitch_lpi, live.pitch_lpi, 1e-9 * live.pitch_lpi);
  EXPECT_NEAR(off.slope, live.slope, 1e-9 * std::abs(live.slope));
  EXPECT_NEAR(off.center_periods, live.center_periods, 1e-7);
  EXPECT_NEAR(offline.calibration.view_cone_measured_deg.value_or(0),
              resumed().outcome->calibration.view_cone_measured_deg.value_or(0), 1e-6);
}

TEST_F(LiveSessionTest, AnUnfinishedSessionIsRefusedOfflineNamingTheResume) {
  (void)resumed();  // the finished session's record, made unfinished below
  const fs::path half = dir_.string() + "-half";
  fs::remove_all(half);
  fs::create_directories(half);
  fs::copy_file(dir_ / "live-session.json", half / "live-session.json");
  {
    LiveSession s(half, LiveSessionPlan{2, 2});  // the same plan opens it
    EXPECT_TRUE(s.position_complete(2, 1));
  }
  // Forget round 2's positions: as if interrupted there.
  std::string text = read_text_file(half / "live-session.json");
  text.replace(text.find("\"round-2\""), 9, "\"round-9\"");
  write_text_atomic(half / "live-session.json", text);
  try {
    (void)capture_folder_of(half);
    FAIL() << "an unfinished last round";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)LiveSession(half, LiveSessionPlan{3, 2}), InputError);  // another plan
  fs::remove_all(half);
}

TEST(LivePositionOrder, LaterRoundsStartWhereTheCameraStands) {
  using Order = std::vector<std::vector<int>>;
  EXPECT_EQ(plan_position_order(2, 3, true), (Order{{0}, {0, 1, 2}}));
  EXPECT_EQ(plan_position_order(3, 2, true), (Order{{0}, {0}, {0, 1}}));
  // Self-calibration needs every position in round 1; round 2 walks back.
  EXPECT_EQ(plan_position_order(2, 3, false), (Order{{0, 1, 2}, {2, 1, 0}}));
  EXPECT_EQ(plan_position_order(3, 3, false), (Order{{0, 1, 2}, {2}, {2, 1, 0}}));
  EXPECT_EQ(plan_position_order(1, 2, false), (Order{{0, 1}}));
  // A panel nobody described: the probes from where the camera stands, then the fine rounds as
  // planned on their own (with intrinsics the camera stays for the first fine position).
  EXPECT_EQ(plan_position_order(2, 3, true, true), (Order{{0}, {0, 1, 2}}));
  EXPECT_EQ(plan_position_order(3, 3, true, true), (Order{{0}, {0}, {0, 1, 2}}));
  EXPECT_EQ(plan_position_order(2, 3, false, true), (Order{{0}, {0, 1, 2}}));
  EXPECT_EQ(plan_position_order(3, 3, false, true), (Order{{0}, {0, 1, 2}, {2, 1, 0}}));
}

TEST(LivePositionOrder, AnUndescribedPanelNeedsTwoRounds) {
  LiveOptions o;
  o.probes = sim::PatternSet{};
  o.rounds = 1;
  EXPECT_THROW(check_live_plan(o), InputError);
  o.rounds = 2;
  EXPECT_NO_THROW(check_live_plan(o));
  o.probes.reset();
  o.rounds = 1;
  EXPECT_NO_THROW(check_live_plan(o));  // a described unit: one round is a round
}

}  // namespace
}  // namespace lfd::live
