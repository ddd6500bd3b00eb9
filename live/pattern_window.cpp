#include "live/pattern_window.hpp"

#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include "live/pattern_window.frag.glsl.hpp"
#include "live/pattern_window.vert.glsl.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {

// Shader problems are bugs of this program, not bad input.
GLuint compile(GLenum stage, const char* source, const char* name) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string(name) + ": " + log);
  }
  return shader;
}

GLuint link_pattern_program() {
  const GLuint vs =
      compile(GL_VERTEX_SHADER, pattern_window_vert_glsl, "pattern_window.vert.glsl");
  const GLuint fs =
      compile(GL_FRAGMENT_SHADER, pattern_window_frag_glsl, "pattern_window.frag.glsl");
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("pattern window program: ") + log);
  }
  return program;
}

// Escape cancels; Enter answers a prompt (PatternWindow::take_enter_press).
void on_key(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER)
    *static_cast<bool*>(glfwGetWindowUserPointer(window)) = true;
}

}  // namespace

PatternWindow::PatternWindow(const gpu::GlfwSession&, GLFWmonitor* monitor, int width_px,
                             int height_px, std::chrono::milliseconds settle)
    : width_(width_px), height_(height_px), settle_(settle) {
  const GLFWvidmode* mode = glfwGetVideoMode(monitor);
  const char* name = glfwGetMonitorName(monitor);
  if (!mode || mode->width != width_px || mode->height != height_px)
    throw_input_error(
        "monitor \"{}\" runs at {}x{}, the display is {}x{}: set it to its native resolution "
        "without rotation or scaling",
        name ? name : "", mode ? mode->width : 0, mode ? mode->height : 0, width_px, height_px);
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // The monitor's current mode, so full screen switches no mode; 8-bit linear channels.
  glfwWindowHint(GLFW_RED_BITS, mode->redBits);
  glfwWindowHint(GLFW_GREEN_BITS, mode->greenBits);
  glfwWindowHint(GLFW_BLUE_BITS, mode->blueBits);
  glfwWindowHint(GLFW_REFRESH_RATE, mode->refreshRate);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_FALSE);
  // The user may answer prompts in a terminal on another monitor: the patterns must stay up
  // when the window loses the focus, and should not take it from the terminal.
  glfwWindowHint(GLFW_AUTO_ICONIFY, GLFW_FALSE);
  glfwWindowHint(GLFW_FOCUSED, GLFW_FALSE);
  glfwWindowHint(GLFW_FOCUS_ON_SHOW, GLFW_FALSE);
  window_ = glfwCreateWindow(width_px, height_px, "lfd calibrate --live", monitor, nullptr);
  if (!window_)
    throw_input_error("cannot open a full-screen OpenGL 3.3 core window on \"{}\": {}",
                      name ? name : "", gpu::GlfwSession::last_error());
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  if (fb_w != width_px || fb_h != height_px) {
    glfwDestroyWindow(window_);
    throw_input_error(
        "the full-screen window on \"{}\" has a {}x{} framebuffer, the display is {}x{}: turn "
        "off desktop scaling for that monitor",
        name ? name : "", fb_w, fb_h, width_px, height_px);
  }
  glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_HIDDEN);  // not in the photographs
  glfwSetWindowUserPointer(window_, &enter_pressed_);
  glfwSetKeyCallback(window_, on_key);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);  // vsync: a swap replaces a whole frame, never half of one

  try {
    program_ = link_pattern_program();
  } catch (...) {
    glfwDestroyWindow(window_);  // the destructor does not run for a failed constructor
    throw;
  }
  glGenVertexArrays(1, &vertex_array_);  // core profile draws need one, even without buffers
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width_px, height_px, 0, GL_RGB, GL_UNSIGNED_BYTE,
               nullptr);
  glDisable(GL_DITHER);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_BLEND);
  glViewport(0, 0, width_px, height_px);
  // Black until the first pattern.
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glfwSwapBuffers(window_);
}

PatternWindow::~PatternWindow() {
  if (!window_) return;
  glfwMakeContextCurrent(window_);
  glDeleteTextures(1, &texture_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(program_);
  glfwDestroyWindow(window_);
}

void PatternWindow::draw() {
  glUseProgram(program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glUniform1i(glGetUniformLocation(program_, "pattern"), 0);
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void PatternWindow::show(const Image8& pattern) {
  if (pattern.width != width_ || pattern.height != height_ || pattern.channels != 3)
    throw_input_error("pattern is {}x{}x{}, the window shows {}x{}x3", pattern.width,
                      pattern.height, pattern.channels, width_, height_);
  poll_events();
  if (glfwWindowShouldClose(window_))
    throw_input_error("the pattern window was closed (Escape): live calibration cancelled");
  glfwMakeContextCurrent(window_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE,
                  pattern.pixels.data());
  has_pattern_ = true;
  // Twice: with vsync and double buffering the second swap cannot complete before the first
  // frame has been scanned out, so when glFinish returns the pattern is on the panel; the
  // settle time covers the panel's response and compositors that queue more frames.
  for (int i = 0; i < 2; ++i) {
    draw();
    glfwSwapBuffers(window_);
  }
  glFinish();
  const auto until = std::chrono::steady_clock::now() + settle_;
  while (std::chrono::steady_clock::now() < until) {
    poll_events();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

Image8 PatternWindow::read_back() {
  Image8 image(width_, height_, 3);
  if (!has_pattern_) return image;  // black, as on screen
  glfwMakeContextCurrent(window_);
  draw();
  glFinish();
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<uint8_t> bottom_up(image.pixels.size());
  glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
  const size_t row = size_t(width_) * 3;
  for (int y = 0; y < height_; ++y)
    std::memcpy(image.row(y), bottom_up.data() + size_t(height_ - 1 - y) * row, row);
  return image;
}

void PatternWindow::poll_events() { glfwPollEvents(); }

bool PatternWindow::take_enter_press() {
  return std::exchange(enter_pressed_, false);
}

}  // namespace lfd::live
