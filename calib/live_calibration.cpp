#include "calib/live_calibration.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "calib/simulated_live_devices.hpp"
#include "util/error.hpp"
#include "util/progress.hpp"

namespace lfd::calib {
namespace {

// The photographs of one camera position, named as `lfd calibrate DIR` would name them, so
// calibrate_display's messages point at "round R, posN/<pattern file>".
PositionCaptures photograph_position(const PatternSet& set, PatternDisplay& display,
                                     FrameSource& camera, int round, int position, int count) {
  PositionCaptures pc;
  pc.name = "pos" + std::to_string(position + 1);
  camera.start_position(position, count);
  display.show(render_pattern(set, *set.of_kind(PatternKind::kWhite).at(0)));
  camera.fix_exposure_on_white();
  Progress progress(fmt::format("round {}, {}", round, pc.name), long(set.patterns.size()));
  for (const PatternInfo& p : set.patterns) {
    display.show(render_pattern(set, p));
    cv::Mat photo = camera.capture();
    if (photo.type() != CV_32FC3)
      throw std::logic_error("FrameSource::capture must return CV_32FC3 RGB");
    const std::string stem = std::filesystem::path(p.file).stem().string();
    pc.images[stem] = std::move(photo);
    pc.paths[stem] = fmt::format("round {}, {}/{}", round, pc.name, p.file);
    progress.advance();
  }
  progress.finish();
  return pc;
}

}  // namespace

CalibrationOutcome run_live_calibration(const Calibration& nominal, PatternDisplay& display,
                                        FrameSource& camera, const LiveOptions& options) {
  const int positions = std::max(1, options.positions);
  Calibration current = nominal;
  CalibrationOutcome outcome;
  for (int round = 1; round <= std::max(1, options.rounds); ++round) {
    const PatternSet set = plan_patterns(current);
    std::vector<PositionCaptures> captures;
    for (int i = 0; i < positions; ++i) {
      if (options.move_camera && (positions > 1 || round == 1)) {
        display.show(render_pattern(set, *set.of_kind(PatternKind::kBoard).at(0)));
        options.move_camera(i + 1, positions);
      }
      captures.push_back(photograph_position(set, display, camera, round, i, positions));
    }
    outcome = calibrate_display(set, captures, options.calibrate);
    if (options.on_round) options.on_round(round, outcome);
    current = outcome.calibration;
    // The next round's patterns use the estimate, but its view cone stays the nominal one
    // (visual.json's viewCone; the measured one is kept separately).
  }
  return outcome;
}

CalibrationOutcome run_live_calibration_simulated(const Calibration& nominal,
                                                  const Calibration& truth,
                                                  const LiveOptions& options) {
  if (truth.display.screen_w != nominal.display.screen_w ||
      truth.display.screen_h != nominal.display.screen_h)
    throw_input_error("--simulate: the true display is {}x{}, the nominal one {}x{}",
                      truth.display.screen_w, truth.display.screen_h, nominal.display.screen_w,
                      nominal.display.screen_h);
  CaptureRig rig =
      make_capture_rig(truth.display, options.capture_width_px, options.positions, false);
  LiveOptions o = options;
  o.calibrate.camera = rig.intrinsics;  // the simulated camera's intrinsics are known exactly
  o.move_camera = nullptr;              // the simulated camera moves itself
  RememberedPattern screen;
  SimulatedCamera camera(truth, std::move(rig), [&screen] { return screen.pattern(); });
  return run_live_calibration(nominal, screen, camera, o);
}

}  // namespace lfd::calib
