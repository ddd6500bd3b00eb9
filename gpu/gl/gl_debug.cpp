#include "gpu/gl/gl_debug.hpp"

#include <cstdio>
#include <mutex>
#include <utility>

#include <epoxy/gl.h>

#include "gpu/gl/gl_program.hpp"

namespace lfd::gpu {
namespace {

std::mutex g_mutex;
std::string g_first_error;

void GLAPIENTRY on_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                 const GLchar* message, const void* user) {
  if (type != GL_DEBUG_TYPE_ERROR) return;
  const std::lock_guard<std::mutex> lock(g_mutex);
  std::fprintf(stderr, "GL debug output: error: %s\n", message);
  if (g_first_error.empty()) g_first_error = message;
}

}  // namespace

void enable_gl_debug_output() {
  if (!strict_gl_checks()) return;
  // OpenGL ES 3.1 has the debug output through KHR_debug only (core in ES 3.2).
  if (!epoxy_is_desktop_gl() && epoxy_gl_version() < 32 && !epoxy_has_gl_extension("GL_KHR_debug")) return;
  glEnable(GL_DEBUG_OUTPUT);
  // Synchronous: the message arrives inside the call that caused it (and before its check_gl).
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(on_debug_message, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::string take_gl_debug_error() {
  const std::lock_guard<std::mutex> lock(g_mutex);
  return std::exchange(g_first_error, std::string());
}

}  // namespace lfd::gpu
