#include "live/hardware_live_calibration.hpp"

#include <chrono>
#include <cstdio>
#include <optional>

#include <fmt/format.h>

#include "live/camera_aiming.hpp"
#include "live/console_prompt.hpp"
#include "live/preview_window.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "live/pattern_window.hpp"
#include "live/video_capture_source.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {

std::string move_prompt(const CameraMove& move) {
  const char* confirm = "press Enter when the preview says good (here, in the preview or in the "
                        "pattern window)";
  if (move.count == 1)
    return fmt::format("point the camera at the display (the whole screen in the photo, the "
                       "board in focus); {}",
                       confirm);
  if (move.revisit)
    return fmt::format("round {}: back to position {} of {}, as before; {}", move.round,
                       move.position, move.count, confirm);
  return fmt::format("move the camera to position {} of {} (another distance and side; the "
                     "whole screen in the photo, the board in focus); {}",
                     move.position, move.count, confirm);
}

// Printed once, before the first prompt: every position the session will ask for.
void print_position_plan(const LiveOptions& options) {
  const auto order = plan_position_order(options.rounds, options.positions,
                                         options.calibrate.camera.has_value(),
                                         options.probes.has_value());
  std::fprintf(stderr, "live calibration: %d round(s) at %d camera position(s):\n",
               options.rounds, options.positions);
  for (size_t r = 0; r < order.size(); ++r) {
    std::string list;
    for (int i : order[r]) list += (list.empty() ? "" : ", ") + std::to_string(i + 1);
    std::fprintf(stderr, "  round %zu: position%s %s%s\n", r + 1, order[r].size() > 1 ? "s" : "",
                 list.c_str(),
                 options.probes && r == 0
                     ? " (the lens probes: head-on, the screen filling 50-70 % of the frame)"
                     : "");
  }
  if (options.positions > 1)
    std::fprintf(stderr,
                 "  positions: clearly different distances (e.g. 0.45, 0.52, 0.60 m) and sides; "
                 "the camera moves only when a prompt asks\n");
  if (!options.session_dir.empty())
    std::fprintf(stderr, "  photos saved in %s (resume with --resume %s)\n",
                 options.session_dir.string().c_str(), options.session_dir.string().c_str());
}

}  // namespace

calib::CalibrationOutcome run_live_calibration_on_hardware(const display::Calibration& nominal,
                                                    const LiveOptions& options) {
  const display::DisplayCalibration& d = nominal.display;
  // Fail before the window and the camera open, not after the first round.
  check_live_plan(options);
  if (!options.calibrate.camera && options.positions < 3)
    throw_input_error(
        "--live with {} camera position(s) needs the camera's intrinsics (--camera "
        "camera.yaml); without them they are self-calibrated from the board at >= 3 positions "
        "(--positions 3)",
        options.positions);

  const gpu::GlfwSession glfw(
      "--live shows the patterns on the display's monitor, so run it in the desktop session the "
      "display is connected to (or use --simulate)");  // "no display: ..." first: nothing to show the patterns on
  GLFWmonitor* monitor = glfw.find_display_monitor(options.monitor_prefix, d.screen_w, d.screen_h);

  VideoCaptureOptions vo;
  vo.index = options.camera_index;
  vo.frames_averaged = options.frames_averaged;
  vo.manage_settings = options.lock_camera_settings;
  if (options.calibrate.camera)
    vo.frame_size = cv::Size(options.calibrate.camera->width, options.calibrate.camera->height);
  // Now, not with the outcome: a round that fails may fail because of it.
  vo.warn = [](const std::string& w) { std::fprintf(stderr, "warning: %s\n", w.c_str()); };
  VideoCaptureSource camera(vo);
  std::fprintf(stderr, "%s\n", camera.describe().c_str());

  PatternWindow window(glfw, monitor, d.screen_w, d.screen_h,
                       std::chrono::milliseconds(options.settle_ms));
  // The preview beside the display, never on it (the camera would see it instead of the board).
  std::optional<PreviewWindow> preview;
  GLFWmonitor* preview_monitor = PreviewWindow::other_monitor(monitor);
  if (options.preview && preview_monitor) preview.emplace(glfw, preview_monitor, 960, 720);
  else if (options.preview)
    std::fprintf(stderr, "no monitor besides the display's: the framing is printed here\n");
  LiveOptions o = options;
  if (!o.move_camera)
    o.move_camera = [&](const CameraMove& move) {
      auto poll_window = [&window] {
        window.poll_events();
        return window.take_enter_press();
      };
      if (!options.preview) return wait_for_enter(move_prompt(move), poll_window);
      aim_camera(camera, *move.set, preview ? &*preview : nullptr, move_prompt(move), poll_window);
    };
  print_position_plan(o);
  return run_live_calibration(nominal, window, camera, o);
}

}  // namespace lfd::live
