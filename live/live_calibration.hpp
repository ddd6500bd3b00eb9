#pragma once
// Live calibration (`lfd calibrate --live`, docs/calibration.md "Live mode"): rounds of show
// patterns -> photograph them -> calibrate, each round making its patterns for the previous round's
// result, so the phase the camera decodes shrinks toward f_seen alone and the last round's estimate
// is made with nearly matched patterns.
//
// One loop, two sets of devices (live/live_devices.hpp):
//   hardware   a full-screen GLFW window on the display's monitor and a cv::VideoCapture
//              camera (live/hardware_live_calibration.hpp; one physical camera, so the
//              user is asked to move it between positions, with a live preview to aim by);
//   simulated  (--simulate TRUTH.json) the pattern is remembered and photographed by the
//              optics simulator looking at a TRUE unit from known poses: the loop's test.
// The camera's exposure, white balance and focus settle on the white pattern once, before
// the session's first photograph, and stay locked for the whole session: every photo of
// every position and round is taken with the same settings. Then every pattern of the
// manifest is shown and photographed in turn; the photographs go to calibrate_display
// exactly as `lfd calibrate DIR` reads them, and with a session folder they are saved as
// they are taken (live/live_session.hpp): re-solvable offline and resumable.
//
// A panel nobody described (LiveOptions::probes; docs/calibration.md, "A panel nobody
// described"): round 1 shows the lens probes of `lfd patterns --screen` and photographs them
// where the camera stands; the lens they show (calib::fine_set_from_probes, what `lfd
// calibrate DIR` does with the same photos offline) draws round 2's fine set, which is
// photographed and solved as a described unit's; later rounds refine as above.
//
// Camera positions are visited as few times as the rounds allow: a round before the last
// only needs one position once the intrinsics are known (given, or self-calibrated by round
// 1 from all positions), so it stays where the camera stands; the last round photographs
// every position, starting where the camera stands. With intrinsics given, each position
// is asked for once.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "calib/calibrate.hpp"
#include "calib/undescribed.hpp"
#include "live/live_devices.hpp"

namespace lfd::live {

// What the user is asked to do before the photographs of a position: bring the camera
// there, aiming at the board on screen.
struct CameraMove {
  int round = 1;
  int position = 1;      // 1-based
  int count = 1;         // positions in the session
  bool revisit = false;  // an earlier round photographed this position
  const sim::PatternSet* set = nullptr;  // the board on screen (its layout, for a preview)
};

struct LiveOptions {
  calib::CalibrateOptions calibrate;
  int rounds = 2;
  int positions = 1;          // camera positions (the last round photographs each)
  int capture_width_px = 640; // simulated: camera width
  // Hardware: the monitor whose GLFW name starts with this (Looking Glass EDID names start
  // with "LKG"); if none or several do, the one at the display's resolution.
  std::string monitor_prefix = "LKG";
  int camera_index = 0;       // hardware: cv::VideoCapture index (/dev/videoN)
  int frames_averaged = 4;    // hardware: frames averaged per photograph (noise / sqrt(n))
  int settle_ms = 200;        // hardware: wait after a pattern is on screen (panel response)
  // Hardware: let exposure, white balance and focus settle on the white pattern once per
  // session, then lock them; false leaves them as the user set them (v4l2-ctl).
  bool lock_camera_settings = true;
  // Hardware: show the camera's live image with the board detection and the framing while
  // the user aims (false: the console prompt alone).
  bool preview = true;
  // Where the photographs are saved as they are taken (live/live_session.hpp); a folder
  // holding a session resumes it. Empty: kept in memory only.
  std::filesystem::path session_dir;
  // Called, with the board on screen, whenever the camera must be brought to a position
  // (not when it already stands there): the hardware mode asks the user and shows the
  // preview. Throwing from it stops the run (the session keeps what was complete).
  std::function<void(const CameraMove&)> move_camera;
  // Called after each round with its number and outcome (progress, tests).
  std::function<void(int, const calib::CalibrationOutcome&)> on_round;
  // A panel nobody described: the coarse set (sim::plan_undescribed_patterns) round 1 shows
  // instead of patterns drawn for a description; rounds >= 2. The nominal passed to the loop
  // is its screen (probes->nominal).
  std::optional<sim::PatternSet> probes;
  // Called after the probes' round with the lens they show and the fine set drawn for it.
  std::function<void(const calib::ProbeRound&)> on_probes;
};

// The positions (0-based) each round photographs, in order (see above): `rounds` lists. With
// `probes_first` round 1 (the probes) photographs where the camera stands (position 1) and the
// rest are planned as `rounds - 1` rounds.
std::vector<std::vector<int>> plan_position_order(int rounds, int positions,
                                                  bool intrinsics_given, bool probes_first = false);

// Refuses (InputError) a plan the loop cannot run: a panel nobody described in fewer than 2
// rounds. The loop checks it first; the hardware mode before the window and camera open.
void check_live_plan(const LiveOptions& options);

// The loop: `options.rounds` rounds starting from the nominal description. Throws
// InputError for captures calibrate_display refuses or a session folder that does not fit.
calib::CalibrationOutcome run_live_calibration(const display::Calibration& nominal, PatternDisplay& display,
                                        FrameSource& camera, const LiveOptions& options);

// The loop against the simulator: the camera (realistic effects, make_capture_rig) looks at
// `truth` from `options.positions` poses; its intrinsics are given to the solver.
calib::CalibrationOutcome run_live_calibration_simulated(const display::Calibration& nominal,
                                                  const display::Calibration& truth,
                                                  const LiveOptions& options);

}  // namespace lfd::live
