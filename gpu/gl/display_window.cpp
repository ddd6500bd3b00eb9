#include "gpu/gl/display_window.hpp"

#include <algorithm>
#include <cmath>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_program.hpp"
#include "util/error.hpp"

namespace lfd::gpu {

namespace {

// The window hints of one context flavour: desktop OpenGL 4.5 core, or OpenGL ES 3.1.
void context_hints(bool es) {
  if (es) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_ANY_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);
  } else {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  }
}

}  // namespace

DisplayWindow::DisplayWindow(const GlfwSession&, GLFWmonitor* monitor, int panel_w,
                             int panel_h, int max_window_px, GlRequest gl)
    : monitor_(monitor), on_display_(monitor != nullptr), panel_w_(panel_w), panel_h_(panel_h) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_FALSE);
  // A debug context under strict checks (the tests), so the driver reports misuse (gl_debug.hpp).
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, strict_gl_checks() ? GLFW_TRUE : GLFW_FALSE);
  int width = panel_w, height = panel_h;
  if (monitor) {
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    glfwWindowHint(GLFW_RED_BITS, mode->redBits);
    glfwWindowHint(GLFW_GREEN_BITS, mode->greenBits);
    glfwWindowHint(GLFW_BLUE_BITS, mode->blueBits);
    glfwWindowHint(GLFW_REFRESH_RATE, mode->refreshRate);
    glfwWindowHint(GLFW_AUTO_ICONIFY, GLFW_FALSE);  // stays up when the control window has focus
    glfwWindowHint(GLFW_FOCUSED, GLFW_FALSE);
    glfwWindowHint(GLFW_FOCUS_ON_SHOW, GLFW_FALSE);
  } else {
    const double scale = std::min(1.0, double(max_window_px) / std::max(panel_w, panel_h));
    width = std::max(1, int(std::lround(panel_w * scale)));
    height = std::max(1, int(std::lround(panel_h * scale)));
  }
  const char* title = monitor ? "lfd view" : "lfd view (simulated display)";
  std::string desktop_why;
  if (gl != GlRequest::kEs) {
    context_hints(false);
    window_ = glfwCreateWindow(width, height, title, monitor, nullptr);
    if (!window_) desktop_why = GlfwSession::last_error();
  }
  if (!window_ && gl != GlRequest::kDesktop) {
    context_hints(true);
    window_ = glfwCreateWindow(width, height, title, monitor, nullptr);
    es_ = window_ != nullptr;
    if (es_ && gl == GlRequest::kAuto) desktop_unavailable_ = desktop_why;
  }
  if (!window_) {
    if (gl == GlRequest::kAuto)
      throw GlUnavailable(fmt::format("no GL: neither an OpenGL 4.5 core window ({}) nor an OpenGL ES 3.1 one ({})",
                                      desktop_why, GlfwSession::last_error()));
    throw GlUnavailable(fmt::format("no GL: no {} window ({})",
                                    gl == GlRequest::kEs ? "OpenGL ES 3.1" : "OpenGL 4.5 core",
                                    GlfwSession::last_error()));
  }
  if (monitor) {
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window_, &fb_w, &fb_h);
    if (fb_w != panel_w || fb_h != panel_h) {
      const char* name = glfwGetMonitorName(monitor);
      glfwDestroyWindow(window_);
      throw_input_error(
          "monitor '{}': the full-screen framebuffer is {}x{}, not the panel's {}x{} (a scaled or "
          "non-native mode); set the display to its native resolution at 100 % scaling",
          name ? name : "", fb_w, fb_h, panel_w, panel_h);
    }
  }
  glfwMakeContextCurrent(window_);
  enable_gl_debug_output();
  glfwSwapInterval(1);  // one frame per vsync: a swap replaces a whole frame
}

DisplayWindow::~DisplayWindow() {
  if (window_) {
    glfwMakeContextCurrent(window_);
    read_fbo_.reset();  // GL objects go while their context is current
    glfwDestroyWindow(window_);
  }
}

void DisplayWindow::make_current() const { glfwMakeContextCurrent(window_); }

void DisplayWindow::set_visible(bool visible) {
  if (visible == this->visible()) return;
  if (visible) {
    glfwShowWindow(window_);
    if (monitor_) glfwSetWindowMonitor(window_, monitor_, 0, 0, panel_w_, panel_h_, GLFW_DONT_CARE);
  } else {
    if (monitor_) glfwSetWindowMonitor(window_, nullptr, 0, 0, panel_w_, panel_h_, GLFW_DONT_CARE);
    glfwHideWindow(window_);
  }
}

bool DisplayWindow::visible() const { return glfwGetWindowAttrib(window_, GLFW_VISIBLE) != 0; }

bool DisplayWindow::should_close() const { return glfwWindowShouldClose(window_); }

void DisplayWindow::draw(const Texture& panel) {
  make_current();
  if (!read_fbo_) read_fbo_ = std::make_unique<Framebuffer>();
  read_fbo_->attach(0, panel);
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w, fb_h);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  // Fit the panel, centred; on the display this is exactly 1:1.
  const double scale = std::min(double(fb_w) / panel.width(), double(fb_h) / panel.height());
  const int w = int(std::lround(panel.width() * scale)), h = int(std::lround(panel.height() * scale));
  const int x0 = (fb_w - w) / 2, y0 = (fb_h - h) / 2;
  // Bound rather than named (glBlitNamedFramebuffer): the one form OpenGL ES 3.1 has too.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo_->id());
  glBlitFramebuffer(0, 0, panel.width(), panel.height(), x0, y0, x0 + w, y0 + h, GL_COLOR_BUFFER_BIT,
                    scale == 1.0 ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  check_gl("presenting the panel");
}

Image8 DisplayWindow::read_back_buffer() const {
  make_current();
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  Image8 out(fb_w, fb_h, 3);
  // RGBA: the one layout OpenGL ES guarantees for reading a window.
  std::vector<uint8_t> rows(size_t(fb_w) * fb_h * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, fb_w, fb_h, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  check_gl("reading the window back");
  // GL rows are bottom-up.
  for (int y = 0; y < fb_h; ++y) {
    const uint8_t* src = rows.data() + size_t(fb_h - 1 - y) * fb_w * 4;
    uint8_t* dst = out.pixels.data() + size_t(y) * fb_w * 3;
    for (int x = 0; x < fb_w; ++x, src += 4, dst += 3) std::copy_n(src, 3, dst);
  }
  return out;
}

void DisplayWindow::swap() { glfwSwapBuffers(window_); }

void DisplayWindow::set_swap_interval(int interval) const {
  make_current();
  glfwSwapInterval(interval);
}

}  // namespace lfd::gpu
