#include "calib/live/hardware_live_calibration.hpp"

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "calib/live/console_prompt.hpp"
#include "gpu/glfw_session.hpp"
#include "calib/live/pattern_window.hpp"
#include "calib/live/video_capture_source.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

std::string move_prompt(int position, int count) {
  if (count == 1)
    return "point the camera at the display (the whole screen in the photo, the board in "
           "focus) and press Enter (here or in the pattern window)";
  return fmt::format(
      "move the camera to position {} of {} (another distance and side; the whole screen in "
      "the photo, the board in focus) and press Enter (here or in the pattern window)",
      position, count);
}

}  // namespace

CalibrationOutcome run_live_calibration_on_hardware(const Calibration& nominal,
                                                    const LiveOptions& options) {
  const DisplayCalibration& d = nominal.display;
  // Fail before the window and the camera open, not after the first round.
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
  LiveOptions o = options;
  if (!o.move_camera)
    o.move_camera = [&window](int position, int count) {
      wait_for_enter(move_prompt(position, count), [&window] {
        window.poll_events();
        return window.take_enter_press();
      });
    };
  return run_live_calibration(nominal, window, camera, o);
}

}  // namespace lfd::calib
