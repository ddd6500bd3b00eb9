#include "gpu/gl/glfw_session.hpp"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <iostream>

#include "gpu/gl/driver_workarounds.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

std::string& last_glfw_error() {
  static std::string text;
  return text;
}

void remember_error(int, const char* description) {
  last_glfw_error() = description ? description : "unknown GLFW error";
}

}  // namespace

// Whether GLFW is up already: another part of the process (a Bridge client that loaded
// libbridge_inproc, docs/bridge-inproc.md "Threads") started it, and it is theirs to end.
static bool glfw_already_initialized() {
  glfwGetError(nullptr);
  glfwGetPrimaryMonitor();
  return glfwGetError(nullptr) != GLFW_NOT_INITIALIZED;
}

GlfwSession::GlfwSession(const std::string& hint) {
  glfwSetErrorCallback(remember_error);
  owns_glfw_ = !glfw_already_initialized();
  last_glfw_error().clear();
  apply_driver_workarounds();
  if (!glfwInit())
    throw_input_error("no display: {}; {}",
                      last_error().empty() ? "GLFW could not start" : last_error(), hint);
}

GlfwSession::~GlfwSession() {
  if (owns_glfw_) glfwTerminate();
}

std::string GlfwSession::last_error() { return last_glfw_error(); }

std::vector<MonitorInfo> GlfwSession::monitors() const {
  int count = 0;
  GLFWmonitor** handles = glfwGetMonitors(&count);
  std::vector<MonitorInfo> out;
  for (int i = 0; i < count; ++i) {
    MonitorInfo m;
    const char* name = glfwGetMonitorName(handles[i]);
    m.name = name ? name : "";
    if (const GLFWvidmode* mode = glfwGetVideoMode(handles[i])) {
      m.width_px = mode->width;
      m.height_px = mode->height;
    }
    out.push_back(m);
  }
  return out;
}

GLFWmonitor* GlfwSession::find_display_monitor(const std::string& name_prefix, int width_px,
                                               int height_px) const {
  const size_t index = display::choose_monitor(monitors(), name_prefix, width_px, height_px);
  int count = 0;
  GLFWmonitor** handles = glfwGetMonitors(&count);
  if (int(index) >= count)  // unplugged just now
    throw_input_error("the monitors changed while looking for the display; try again");
  return handles[index];
}

GLFWmonitor* GlfwSession::display_monitor_or_none(const std::string& name_prefix, int width_px,
                                                  int height_px) const {
  try {
    return find_display_monitor(name_prefix, width_px, height_px);
  } catch (const InputError& e) {
    std::cerr << fmt::format("notice: no monitor for the display ({}); showing a simulated display in a window\n",
                             e.what());
  }
  return nullptr;
}

}  // namespace lfd::gpu
