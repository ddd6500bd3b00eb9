#pragma once
// The live calibration's display (live/live_devices.hpp): a full-screen window on the
// display's monitor at the monitor's current video mode, drawing each pattern 1:1 (one texel
// per panel pixel, no filtering, no scaling, no sRGB conversion) with vsync. The panel must
// show the pattern's exact subpixel values: a scaled or colour-converted pattern is a
// different phase pattern. The window and its GL 4.5 core context are gpu::DisplayWindow's (the
// one `lfd play` and `lfd view` show the panel in), the GL objects gpu/'s wrappers.
#include <chrono>
#include <memory>

#include "gpu/gl/display_window.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "live/live_devices.hpp"

namespace lfd::live {

class PatternWindow : public PatternDisplay {
 public:
  // Opens the window on `monitor` (gpu::GlfwSession::find_display_monitor), which must be
  // width_px x height_px with a framebuffer of that size (no desktop scaling). `settle` is
  // how long show() waits once the pattern is on screen (the panel's response). Throws
  // InputError when the window or a GL 4.5 core context cannot be made.
  PatternWindow(const gpu::GlfwSession& session, GLFWmonitor* monitor, int width_px, int height_px,
                std::chrono::milliseconds settle = std::chrono::milliseconds(0));
  ~PatternWindow() override;
  PatternWindow(const PatternWindow&) = delete;
  PatternWindow& operator=(const PatternWindow&) = delete;

  // Draws `pattern` (width_px x height_px, 3 channels), swaps on vsync, waits for the GPU and
  // then `settle`. Throws InputError if the pattern has the wrong size or the user closed the
  // window (Escape).
  void show(const Image8& pattern) override;
  // The shown pattern as the framebuffer holds it (glReadPixels of a fresh draw; row 0 = top).
  Image8 read_back();
  // Handles window events (keeps the window responsive while the program waits for input).
  void poll_events();
  // True once per press of Enter in the window since the last call (handled by poll_events):
  // the user at the camera may answer a prompt there while the terminal lacks the focus.
  bool take_enter_press();

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void draw();

  int width_ = 0, height_ = 0;
  std::chrono::milliseconds settle_;
  std::unique_ptr<gpu::DisplayWindow> window_;  // before the GL objects: they go first
  gpu::Program program_;
  gpu::Texture texture_;
  std::unique_ptr<gpu::VertexArray> vertex_array_;
  bool has_pattern_ = false;
  bool enter_pressed_ = false;
};

}  // namespace lfd::live
