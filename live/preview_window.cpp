#include "live/preview_window.hpp"

#include <algorithm>
#include <utility>

#include <epoxy/gl.h>  // before GLFW, which would include GL/gl.h
#include <GLFW/glfw3.h>
#include <opencv2/core.hpp>

#include "util/error.hpp"

namespace lfd::live {
namespace {

void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER || key == GLFW_KEY_SPACE)
    *static_cast<bool*>(glfwGetWindowUserPointer(window)) = true;
}

}  // namespace

PreviewWindow::PreviewWindow(const gpu::GlfwSession& session, GLFWmonitor* monitor, int width_px,
                             int height_px) {
  // No monitor: a normal window, width_px x height_px (nothing to fit it into).
  window_ = std::make_unique<gpu::DisplayWindow>(session, nullptr, width_px, height_px,
                                                 std::max(width_px, height_px));
  GLFWwindow* handle = window_->handle();
  glfwSetWindowTitle(handle, "lfd calibrate --live: aim the camera");
  if (monitor) {
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
    glfwSetWindowPos(handle, x + 40, y + 40);
  }
  glfwSetWindowUserPointer(handle, &enter_pressed_);
  glfwSetKeyCallback(handle, on_key);
  window_->set_swap_interval(0);  // the camera paces the frames, not the monitor
}

PreviewWindow::~PreviewWindow() {
  if (window_) window_->make_current();  // the texture goes (before the window) while it is current
}

GLFWmonitor* PreviewWindow::other_monitor(GLFWmonitor* display) {
  int count = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&count);
  for (int i = 0; i < count; ++i)
    if (monitors[i] != display) return monitors[i];
  return nullptr;
}

void PreviewWindow::show(const cv::Mat& rgb8) {
  CV_Assert(rgb8.type() == CV_8UC3);
  window_->make_current();
  // DisplayWindow shows a texture's row 0 at the bottom (GL's order); the frame's row 0 is its top.
  cv::flip(rgb8, bottom_up_, 0);
  if (texture_.width() != bottom_up_.cols || texture_.height() != bottom_up_.rows)
    texture_ = gpu::Texture(GL_RGBA8, bottom_up_.cols, bottom_up_.rows);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, bottom_up_.cols, bottom_up_.rows, GL_RGB, GL_UNSIGNED_BYTE,
                      bottom_up_.data);
  draw();
  window_->swap();
}

void PreviewWindow::draw() {
  if (texture_.id()) {
    window_->draw(texture_);  // fitted, keeping its aspect, black bars
    glFinish();
    return;
  }
  window_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}

cv::Mat PreviewWindow::read_back() {
  draw();  // the back buffer again: the front one may not be readable
  const Image8 shown = window_->read_back_buffer();
  return cv::Mat(shown.height, shown.width, CV_8UC3, const_cast<uint8_t*>(shown.pixels.data())).clone();
}

bool PreviewWindow::poll_enter() {
  glfwPollEvents();
  return std::exchange(enter_pressed_, false);
}

bool PreviewWindow::closed() const { return window_->should_close(); }

}  // namespace lfd::live
