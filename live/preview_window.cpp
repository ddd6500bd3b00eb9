#include "live/preview_window.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

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

PreviewWindow::PreviewWindow(const gpu::GlfwSession&, GLFWmonitor* monitor, int width_px,
                             int height_px) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown once placed
  window_ = glfwCreateWindow(width_px, height_px, "lfd calibrate --live: aim the camera",
                             nullptr, nullptr);
  if (!window_)
    throw_input_error("cannot open the camera preview window: {}", gpu::GlfwSession::last_error());
  if (monitor) {
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
    glfwSetWindowPos(window_, x + 40, y + 40);
  }
  glfwShowWindow(window_);
  glfwSetWindowUserPointer(window_, &enter_pressed_);
  glfwSetKeyCallback(window_, on_key);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // the camera paces the frames, not the monitor
  glGenTextures(1, &texture_);
  glGenFramebuffers(1, &framebuffer_);
}

PreviewWindow::~PreviewWindow() {
  glfwMakeContextCurrent(window_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &texture_);
  glfwDestroyWindow(window_);
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
  glfwMakeContextCurrent(window_);
  const cv::Mat pixels = rgb8.isContinuous() ? rgb8 : rgb8.clone();
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (pixels.size() != texture_size_) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, pixels.cols, pixels.rows, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, pixels.data);
    texture_size_ = pixels.size();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, pixels.cols, pixels.rows, GL_RGB, GL_UNSIGNED_BYTE,
                    pixels.data);
  }
  draw();
  glfwSwapBuffers(window_);
}

void PreviewWindow::draw() {
  // A blit scales without a shader; the frame's row 0 (its top) goes to the window's top.
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  const double scale =
      std::min(double(fb_w) / texture_size_.width, double(fb_h) / texture_size_.height);
  const int w = int(texture_size_.width * scale), h = int(texture_size_.height * scale);
  const int x0 = (fb_w - w) / 2, y0 = (fb_h - h) / 2;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w, fb_h);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glBlitFramebuffer(0, 0, texture_size_.width, texture_size_.height, x0, y0 + h, x0 + w, y0,
                    GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glFinish();
}

cv::Mat PreviewWindow::read_back() {
  glfwMakeContextCurrent(window_);
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  cv::Mat bottom_up(fb_h, fb_w, CV_8UC3), out;
  if (texture_size_.area()) draw();  // the back buffer again: the front one may not be readable
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, fb_w, fb_h, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data);
  cv::flip(bottom_up, out, 0);
  return out;
}

bool PreviewWindow::poll_enter() {
  glfwPollEvents();
  return std::exchange(enter_pressed_, false);
}

bool PreviewWindow::closed() const { return glfwWindowShouldClose(window_); }

}  // namespace lfd::live
