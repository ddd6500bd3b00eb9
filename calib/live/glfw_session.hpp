#pragma once
// GLFW for the live calibration's pattern window: initialised while a session lives, with
// GLFW's own error text kept for messages. Without an X server there is nothing to show the
// patterns on, which is bad input to `lfd calibrate --live` (InputError), not a crash.
#include <string>
#include <vector>

#include "calib/display/monitor_choice.hpp"

struct GLFWmonitor;

namespace lfd::calib {

class GlfwSession {
 public:
  // Throws InputError "no display: <GLFW's reason>" when GLFW cannot start.
  GlfwSession();
  ~GlfwSession();
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;

  // Connected monitors with their current video modes, in GLFW's order.
  std::vector<MonitorInfo> monitors() const;
  // The monitor for a display of width_px x height_px (choose_monitor's rule).
  GLFWmonitor* find_display_monitor(const std::string& name_prefix, int width_px,
                                    int height_px) const;
  // GLFW's description of its most recent error ("" if none).
  static std::string last_error();
};

}  // namespace lfd::calib
