#include "live/pattern_window.hpp"

#include <thread>
#include <utility>

#include <epoxy/gl.h>  // before GLFW, which would include GL/gl.h
#include <GLFW/glfw3.h>

#include "live/shaders/pattern_window.frag.glsl.hpp"
#include "live/shaders/pattern_window_io.h"
#include "live/shaders/pattern_window.vert.glsl.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {

// Escape cancels; Enter answers a prompt (PatternWindow::take_enter_press).
void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER)
    *static_cast<bool*>(glfwGetWindowUserPointer(window)) = true;
}

}  // namespace

PatternWindow::PatternWindow(const gpu::GlfwSession& session, GLFWmonitor* monitor, int width_px,
                             int height_px, std::chrono::milliseconds settle)
    : width_(width_px), height_(height_px), settle_(settle) {
  const GLFWvidmode* mode = glfwGetVideoMode(monitor);
  const char* name = glfwGetMonitorName(monitor);
  if (!mode || mode->width != width_px || mode->height != height_px)
    throw_input_error(
        "monitor \"{}\" runs at {}x{}, the display is {}x{}: set it to its native resolution "
        "without rotation or scaling",
        name ? name : "", mode ? mode->width : 0, mode ? mode->height : 0, width_px, height_px);
  // Full screen at the monitor's current mode (no mode switch), 8-bit linear channels, a
  // framebuffer of the panel's size or an InputError; it stays up without the focus and does
  // not take it from the terminal where the user answers prompts.
  window_ = std::make_unique<gpu::DisplayWindow>(session, monitor, width_px, height_px);
  GLFWwindow* handle = window_->handle();
  glfwSetWindowTitle(handle, "lfd calibrate --live");
  glfwSetInputMode(handle, GLFW_CURSOR, GLFW_CURSOR_HIDDEN);  // not in the photographs
  glfwSetWindowUserPointer(handle, &enter_pressed_);
  glfwSetKeyCallback(handle, on_key);
  window_->make_current();  // vsync (DisplayWindow): a swap replaces a whole frame, never half of one

  program_ = gpu::Program("pattern window",
                          {{GL_VERTEX_SHADER, pattern_window_vert_glsl}, {GL_FRAGMENT_SHADER, pattern_window_frag_glsl}},
                          {}, {gpu::texture("pattern", kPatternUnit)});
  texture_ = gpu::Texture(GL_RGBA8, width_px, height_px);
  vertex_array_ = std::make_unique<gpu::VertexArray>();  // core profile draws need one, even without buffers
  glDisable(GL_DITHER);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_BLEND);
  // Black until the first pattern.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width_px, height_px);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  window_->swap();
}

PatternWindow::~PatternWindow() {
  if (window_) window_->make_current();  // the GL objects go (before the window) while it is current
}

void PatternWindow::draw() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width_, height_);
  program_.use();
  program_.bind("pattern", texture_);
  glBindVertexArray(vertex_array_->id());
  program_.draw_arrays(GL_TRIANGLES, 0, 3);
}

void PatternWindow::show(const Image8& pattern) {
  if (pattern.width != width_ || pattern.height != height_ || pattern.channels != 3)
    throw_input_error("pattern is {}x{}x{}, the window shows {}x{}x3", pattern.width,
                      pattern.height, pattern.channels, width_, height_);
  poll_events();
  if (window_->should_close())
    throw_input_error("the pattern window was closed (Escape): live calibration cancelled");
  window_->make_current();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE,
                      pattern.pixels.data());
  has_pattern_ = true;
  // Twice: with vsync and double buffering the second swap cannot complete before the first
  // frame has been scanned out, so when glFinish returns the pattern is on the panel; the
  // settle time covers the panel's response and compositors that queue more frames.
  for (int i = 0; i < 2; ++i) {
    draw();
    window_->swap();
  }
  glFinish();
  const auto until = std::chrono::steady_clock::now() + settle_;
  while (std::chrono::steady_clock::now() < until) {
    poll_events();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

Image8 PatternWindow::read_back() {
  if (!has_pattern_) return Image8(width_, height_, 3);  // black, as on screen
  window_->make_current();
  draw();
  return window_->read_back_buffer();
}

void PatternWindow::poll_events() { glfwPollEvents(); }

bool PatternWindow::take_enter_press() {
  return std::exchange(enter_pressed_, false);
}

}  // namespace lfd::live
