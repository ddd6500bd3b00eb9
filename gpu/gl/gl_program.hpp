#pragma once
// A linked GL program, and the checks that keep a pass's C++ and GLSL sides agreeing
// (docs/gpu.md "Shaders and their contracts"):
// - an embedded shader's compile errors name its files and lines (cmake/embed_shader.py);
// - a uniform the C++ side asks for that the shader does not declare throws, naming both;
// - two resources of one program on one binding point throw at link time, naming both;
// - with strict GL checks (the tests: LFD_GL_CHECKS=strict), a declared uniform the compiler
//   found unused also throws when asked for, and the GL debug output turns driver errors into
//   exceptions (gpu/gl/gl_debug.hpp).
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_name.hpp"

namespace lfd::gpu {


class Program {
 public:
  Program() = default;
  // Stages are (GL_*_SHADER, source); sources get the version line and `defines` ("NAME VALUE"
  // lines) prepended, so one file serves several variants. Compile and link errors throw
  // std::runtime_error naming `label` with the driver's log.
  Program(const std::string& label, const std::vector<std::pair<GLenum, const char*>>& stages,
          const std::vector<std::string>& defines = {});
  GLuint id() const { return name_.id(); }
  const std::string& label() const { return label_; }
  void use() const;
  // The location of a uniform the sources declare: -1 when the compiler optimised it away (a
  // variant that does not use it; std::logic_error under strict checks). A name the sources do
  // not declare throws std::logic_error. Looked up in a table made at link time (no
  // glGetUniformLocation, a driver round trip, per frame; docs/gpu.md "A frame that never waits").
  GLint uniform(const char* name) const;
  // Dispatches ceil(n / local_size) groups of the compute program (1D).
  void dispatch_1d(size_t items, int local_size) const;

 private:
  void list_uniforms();   // fills active_ after the link
  void check_bindings();  // throws when two resources share a binding point
  void check_work_group_fits() const;  // a compute program's group within the device's invocations

  GlName<delete_program> name_;
  std::string label_;
  std::vector<std::string> declared_;                  // uniforms the sources declare
  std::vector<std::pair<std::string, GLint>> active_;  // active uniforms and their locations
};

// Whether strict GL checks are on: LFD_GL_CHECKS=strict in the environment (set for every test
// by tests/CMakeLists.txt).
bool strict_gl_checks();

}  // namespace lfd::gpu
