#pragma once
// The live preview while the user aims the camera: an ordinary window (not full screen) on a
// monitor other than the display's, showing camera frames scaled to fit. It must not sit on
// the display's panel: the camera would photograph it instead of the board. The window is a
// gpu::DisplayWindow without a monitor (a normal window showing a picture fitted), the frame a
// gpu::Texture.
#include <memory>

#include <opencv2/core.hpp>

#include "gpu/gl/display_window.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/glfw_session.hpp"

namespace lfd::live {

class PreviewWindow {
 public:
  // Opens a width_px x height_px window on `monitor` (its work area's top-left corner), or
  // where the window system puts it when `monitor` is null. Throws InputError when no
  // window or GL 4.5 core context can be made.
  PreviewWindow(const gpu::GlfwSession& session, GLFWmonitor* monitor, int width_px,
                int height_px);
  ~PreviewWindow();
  PreviewWindow(const PreviewWindow&) = delete;
  PreviewWindow& operator=(const PreviewWindow&) = delete;

  // A monitor other than `display` (the first such), or null when there is none.
  static GLFWmonitor* other_monitor(GLFWmonitor* display);

  // Draws `rgb8` (CV_8UC3, RGB, row 0 = top) scaled to fit, keeping its aspect, and swaps.
  void show(const cv::Mat& rgb8);
  // The window's content as last drawn (RGB8, row 0 = top; for tests).
  cv::Mat read_back();
  // Handles window events; true once per press of Enter (or Space) since the last call.
  bool poll_enter();
  // True when the user closed the window or pressed Escape in it.
  bool closed() const;

 private:
  void draw();  // the last frame into the back buffer

  std::unique_ptr<gpu::DisplayWindow> window_;  // before the texture: it goes first
  gpu::Texture texture_;  // the last frame, rows bottom-up (GL's order)
  cv::Mat bottom_up_;     // the frame flipped for the upload, kept between frames
  bool enter_pressed_ = false;
};

}  // namespace lfd::live
