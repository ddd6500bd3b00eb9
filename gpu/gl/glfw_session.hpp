#pragma once
// GLFW, the window kind of GL context (the live calibration's pattern window, the viewer):
// initialised while a session lives (ended with it unless something else in the process had
// started GLFW before), with GLFW's own error text kept for messages. Without an X
// server there is nothing to show a window on, which is bad input (InputError), not a crash.
// One monitor rule for every window on the display: display::choose_monitor.
#include <string>
#include <vector>

#include "display/monitor_choice.hpp"

struct GLFWmonitor;

namespace lfd::gpu {

using display::MonitorInfo;

class GlfwSession {
 public:
  // Throws InputError "no display: <GLFW's reason>; <hint>" when GLFW cannot start; `hint` says
  // what the command needs the window for and what to do instead.
  explicit GlfwSession(const std::string& hint = "run it in the desktop session the display is connected to");
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;

  // Connected monitors with their current video modes, in GLFW's order.
  std::vector<MonitorInfo> monitors() const;
  // The monitor for a display of width_px x height_px (choose_monitor's rule).
  GLFWmonitor* find_display_monitor(const std::string& name_prefix, int width_px,
                                    int height_px) const;
  // The same, or nullptr with a notice on stderr when the display is not connected: the caller
  // shows a simulated display in a window instead (`lfd view`, `lfd play`).
  GLFWmonitor* display_monitor_or_none(const std::string& name_prefix, int width_px, int height_px) const;
  // GLFW's description of its most recent error ("" if none).
  static std::string last_error();

 private:
  bool owns_glfw_ = true;  // this session started GLFW, so it ends it (glfwTerminate)
};

}  // namespace lfd::gpu
