#pragma once
// The window that shows the interlaced panel. On the display's monitor: borderless full screen
// at the panel's native resolution, one framebuffer pixel per panel pixel (anything else
// scrambles the views, so a scaled or non-native mode is refused). Without a display: a normal
// window showing the panel fitted, as a simulated display. It owns the GL 4.5 core context every
// renderer of the viewer draws with; the control window shares its textures. The display side
// (`lfd play`, `lfd serve`) may take an OpenGL ES 3.1 context instead (gl_flavour.hpp).
#include <memory>
#include <vector>

#include <string>

#include "gpu/gl/gl_flavour.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "util/image.hpp"

struct GLFWwindow;
struct GLFWmonitor;

namespace lfd::gpu {

class DisplayWindow {
 public:
  // `monitor` null: the simulated display window (panel fitted in at most `max_window_px`).
  // Throws InputError naming the monitor and its mode when the framebuffer does not come out at
  // the panel's size, and "no GL: ..." when no GL 4.5 core context can be made. `gl`: desktop
  // (GL 4.5 core: the viewer), es (OpenGL ES 3.1) or auto (desktop, else ES: es() and
  // desktop_unavailable() say which and why; the caller prints es_fallback_notice).
  DisplayWindow(const GlfwSession& session, GLFWmonitor* monitor, int panel_w, int panel_h,
                int max_window_px = 1024, GlRequest gl = GlRequest::kDesktop);
  ~DisplayWindow();
  DisplayWindow(const DisplayWindow&) = delete;
  DisplayWindow& operator=(const DisplayWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool on_display() const { return on_display_; }
  bool es() const { return es_; }
  // Why desktop OpenGL 4.5 could not be made when auto took ES ("" otherwise).
  const std::string& desktop_unavailable() const { return desktop_unavailable_; }
  void make_current() const;
  bool should_close() const;
  // Draws the panel texture (panel-size) into the back buffer: 1:1 on the display, fitted
  // (linear filter, black bars) in the simulated window.
  void draw(const Texture& panel);
  // What draw() put in the back buffer, rows top-down (the screenshot of the window).
  Image8 read_back_buffer() const;
  void swap();
  // 1 (the default): one frame per vsync; 0: swaps do not wait for it (lfd view --no-vsync).
  void set_swap_interval(int interval) const;
  // Hides the window or shows it again (Bridge's show_window). A full-screen window leaves its
  // monitor to hide (GLFW cannot hide a full-screen window) and takes it again, at the panel's
  // size, to show.
  void set_visible(bool visible);
  bool visible() const;

 private:
  GLFWwindow* window_ = nullptr;
  GLFWmonitor* monitor_ = nullptr;  // the display's, when full screen on it
  bool on_display_ = false;
  bool es_ = false;
  std::string desktop_unavailable_;
  int panel_w_ = 0, panel_h_ = 0;
  std::unique_ptr<Framebuffer> read_fbo_;  // reads the panel texture for the blit
};

}  // namespace lfd::gpu
