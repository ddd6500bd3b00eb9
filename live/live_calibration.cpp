#include "live/live_calibration.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "live/live_session.hpp"
#include "live/simulated_live_devices.hpp"
#include "util/error.hpp"
#include "util/progress.hpp"

namespace lfd::live {
namespace {

// Self-calibration needs the board from this many positions (calibrate_display refuses fewer).
constexpr size_t kSelfCalibrationPositions = 3;

// What the loop needs from a session folder, and nothing when there is none.
struct PhotoSink {
  LiveSession* session = nullptr;
  int round = 1;
};

// The photographs of one camera position. Messages name the saved files, or "round R,
// posN/<pattern file>" without a session folder.
sim::PositionCaptures photograph_position(const sim::PatternSet& set, PatternDisplay& display,
                                     FrameSource& camera, const PhotoSink& sink, int index,
                                     int count, bool& settings_locked) {
  sim::PositionCaptures pc;
  pc.name = LiveSession::position_name(index);
  if (sink.session) sink.session->begin_position(sink.round, index);
  camera.start_position(index, count);
  if (!settings_locked) {  // once per session: every photo is taken with the same settings
    display.show(sim::render_pattern(set, *set.of_kind(sim::PatternKind::kWhite).at(0)));
    camera.fix_exposure_on_white();
    settings_locked = true;
  }
  Progress progress(fmt::format("round {}, {}", sink.round, pc.name), long(set.patterns.size()));
  for (const sim::PatternInfo& p : set.patterns) {
    display.show(sim::render_pattern(set, p));
    cv::Mat photo = camera.capture();
    if (photo.type() != CV_32FC3)
      throw std::logic_error("FrameSource::capture must return CV_32FC3 RGB");
    const std::string stem = std::filesystem::path(p.file).stem().string();
    std::string path = fmt::format("round {}, {}/{}", sink.round, pc.name, p.file);
    if (sink.session) photo = sink.session->save_photo(sink.round, index, stem, photo, path);
    pc.images[stem] = std::move(photo);
    pc.paths[stem] = path;
    progress.advance();
  }
  progress.finish();
  if (sink.session) sink.session->complete_position(sink.round, index);
  return pc;
}

// The round's patterns: those a resumed round began with, else `make()`.
sim::PatternSet round_patterns(LiveSession* session, int round,
                               const std::function<sim::PatternSet()>& make) {
  if (!session) return make();
  if (auto saved = session->saved_patterns(round)) return *saved;
  return session->save_patterns(round, make());
}

}  // namespace

std::vector<std::vector<int>> plan_position_order(int rounds, int positions,
                                                  bool intrinsics_given, bool probes_first) {
  rounds = std::max(1, rounds);
  positions = std::max(1, positions);
  std::vector<std::vector<int>> order;
  if (probes_first) {
    order.push_back({0});
    for (auto& here : plan_position_order(rounds - 1, positions, intrinsics_given))
      order.push_back(std::move(here));
    return order;
  }
  int camera_at = 0;
  for (int r = 1; r <= rounds; ++r) {
    const bool intrinsics_known = intrinsics_given || r > 1;  // round 1 self-calibrates them
    std::vector<int> here;
    if (r < rounds && intrinsics_known) {
      here = {camera_at};
    } else {
      // Every position, from the end the camera stands at (no move between rounds).
      for (int i = 0; i < positions; ++i) here.push_back(i);
      if (camera_at != 0) std::reverse(here.begin(), here.end());
    }
    camera_at = here.back();
    order.push_back(std::move(here));
  }
  return order;
}

void check_live_plan(const LiveOptions& options) {
  if (options.probes && options.rounds < 2)
    throw_input_error("--rounds {}: a panel nobody described needs 2 rounds or more (the lens "
                      "probes, then the fine set drawn for the lens they show)",
                      options.rounds);
}

calib::CalibrationOutcome run_live_calibration(const display::Calibration& nominal, PatternDisplay& display,
                                        FrameSource& camera, const LiveOptions& options) {
  const int positions = std::max(1, options.positions);
  const int rounds = std::max(1, options.rounds);
  check_live_plan(options);
  const sim::PatternSet* probes = options.probes ? &*options.probes : nullptr;
  const int first_solve = probes ? 2 : 1;  // the round whose photos calibrate_display solves first
  std::optional<LiveSession> session;
  if (!options.session_dir.empty()) session.emplace(options.session_dir, LiveSessionPlan{rounds, positions});
  const auto order =
      plan_position_order(rounds, positions, options.calibrate.camera.has_value(), probes);

  display::Calibration current = nominal;
  calib::CalibrationOutcome outcome;
  bool settings_locked = false;
  int camera_at = -1;  // unknown until the first position of this run
  for (int round = 1; round <= rounds; ++round) {
    const std::vector<int>& here = order[size_t(round - 1)];
    calib::CalibrateOptions co = options.calibrate;
    // Too few positions to self-calibrate: the previous round's self-calibrated intrinsics.
    if (!co.camera && here.size() < kSelfCalibrationPositions && round > first_solve)
      co.camera = outcome.camera;
    LiveSession* s = session ? &*session : nullptr;
    const sim::PatternSet set = round_patterns(s, round, [&] {
      if (probes) return round == 1 ? *probes : calib::plan_fine_patterns(*probes, current);
      return sim::plan_patterns(current);
    });
    if (s) s->save_camera(round, co.camera);

    std::map<int, sim::PositionCaptures> captures;  // by position, as `lfd calibrate` orders them
    for (int index : here) {
      if (s && s->position_complete(round, index)) {
        captures[index] = s->read_position(round, index, set);
        continue;
      }
      if (camera_at != index) {
        display.show(sim::render_pattern(set, *set.of_kind(sim::PatternKind::kBoard).at(0)));
        bool revisit = false;
        for (int r = 1; r < round; ++r)
          revisit |= std::count(order[size_t(r - 1)].begin(), order[size_t(r - 1)].end(), index) > 0;
        if (options.move_camera)
          options.move_camera(CameraMove{round, index + 1, positions, revisit, &set});
        camera_at = index;
      }
      captures[index] = photograph_position(set, display, camera, PhotoSink{s, round}, index,
                                            positions, settings_locked);
    }
    std::vector<sim::PositionCaptures> list;
    for (auto& [index, pc] : captures) list.push_back(std::move(pc));
    if (set.undescribed) {  // the probes: the lens they show draws the next round's patterns
      const calib::ProbeRound found = calib::fine_set_from_probes(set, list.front());
      if (options.on_probes) options.on_probes(found);
      current = found.description;
      continue;
    }
    outcome = calib::calibrate_display(set, list, co);
    if (options.on_round) options.on_round(round, outcome);
    current = outcome.calibration;
    // The next round's patterns use the estimate, but its view cone stays the nominal one
    // (visual.json's viewCone; the measured one is kept separately).
  }
  return outcome;
}

calib::CalibrationOutcome run_live_calibration_simulated(const display::Calibration& nominal,
                                                  const display::Calibration& truth,
                                                  const LiveOptions& options) {
  if (truth.display.screen_w != nominal.display.screen_w ||
      truth.display.screen_h != nominal.display.screen_h)
    throw_input_error("--simulate: the true display is {}x{}, the nominal one {}x{}",
                      truth.display.screen_w, truth.display.screen_h, nominal.display.screen_w,
                      nominal.display.screen_h);
  sim::CaptureRig rig =
      sim::make_capture_rig(truth.display, options.capture_width_px, options.positions, false);
  LiveOptions o = options;
  o.calibrate.camera = rig.intrinsics;  // the simulated camera's intrinsics are known exactly
  RememberedPattern screen;
  SimulatedCamera camera(truth, std::move(rig), [&screen] { return screen.pattern(); });
  return run_live_calibration(nominal, screen, camera, o);
}

}  // namespace lfd::live
