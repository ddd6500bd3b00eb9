#pragma once
// A linked GL program, and the checks that keep a pass's C++ and GLSL sides agreeing
// (docs/gpu.md "Shaders and their contracts"):
// - an embedded shader's compile errors name its files and lines (cmake/embed_shader.py);
// - a uniform the C++ side asks for that the shader does not declare throws, naming both;
// - two resources of one program on one binding point throw at link time, naming both;
// - with strict GL checks (the tests: LFD_GL_CHECKS=strict), a declared uniform the compiler
//   found unused also throws when asked for, and the GL debug output turns driver errors into
//   exceptions (gpu/gl/gl_debug.hpp);
// - a program that declares its bindings (gpu/gl/gl_bindings.hpp) is checked against them at
//   link time, is bound by declared name, and under strict checks its dispatches and draws throw
//   when a declared point holds something else than the pass bound (docs/gpu.md "Binding points").
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_bindings.hpp"
#include "gpu/gl/gl_name.hpp"

namespace lfd::gpu {

class Buffer;
class Texture;

class Program {
 public:
  Program() = default;
  // Stages are (GL_*_SHADER, source); sources get the version line and `defines` ("NAME VALUE"
  // lines) prepended, so one file serves several variants. Compile and link errors throw
  // std::runtime_error naming `label` with the driver's log. `bindings` declares what the program
  // reads and writes at which point; when given it must match the program's active resources
  // (std::logic_error naming the point). A program that declares nothing is not checked (a test's
  // own shader); every pass of lfd declares.
  Program(const std::string& label, const std::vector<std::pair<GLenum, const char*>>& stages,
          const std::vector<std::string>& defines = {}, std::vector<Binding> bindings = {});
  GLuint id() const { return name_.id(); }
  const std::string& label() const { return label_; }
  void use() const;
  // The location of a uniform the sources declare: -1 when the compiler optimised it away (a
  // variant that does not use it; std::logic_error under strict checks). A name the sources do
  // not declare throws std::logic_error. Looked up in a table made at link time (no
  // glGetUniformLocation, a driver round trip, per frame; docs/gpu.md "A frame that never waits").
  GLint uniform(const char* name) const;

  // Binds `buffer` (a storage or uniform buffer), or `texture` (a texture unit, or an image unit
  // with the declared access, every layer of an array), at the point declared as `name`, and
  // records it for the check before use. std::logic_error for a name not declared or of another
  // kind. Const: what it changes is GL's state and the program's record of it, not the program.
  void bind(const std::string& name, const Buffer& buffer) const;
  void bind(const std::string& name, const Texture& texture) const;
  void bind_texture_id(const std::string& name, GLuint texture) const;  // a texture lfd does not own
  // Whether the program declares a binding `name`: a helper that binds for its clients (the tile
  // keys' buffers) binds only the points the client's program reads.
  bool declares(const std::string& name) const;

  // Dispatches and draws of this program, which must be in use. Under strict checks each first
  // checks the declared bindings (check_bindings_before_use).
  void dispatch(GLuint x, GLuint y = 1, GLuint z = 1) const;
  // ceil(n / local_size) groups (1D; past 65535 groups spread over y: shaders use gl_NumWorkGroups).
  void dispatch_1d(size_t items, int local_size) const;
  // `groups` groups (one a block, a slot...) spread over rows of at most 65535, `z` deep; nothing
  // for 0 groups (gpu/gl/gl_work_groups.hpp: the shaders use flat_group_index()).
  void dispatch_groups(size_t groups, GLuint z = 1) const;
  void dispatch_indirect(GLintptr offset) const;  // from the bound GL_DISPATCH_INDIRECT_BUFFER
  void draw_arrays(GLenum mode, GLint first, GLsizei count, GLsizei instances = 1) const;
  void draw_arrays_indirect(GLenum mode, GLintptr offset) const;  // from GL_DRAW_INDIRECT_BUFFER
  // Under strict checks: throws std::logic_error, naming the pass and the point, when this program
  // is not in use, a declared point was never bound through bind(), or GL holds another object
  // there than the one bound. Nothing without strict checks. The entry points above call it.
  void check_bindings_before_use() const;

 private:
  void list_uniforms();   // fills active_ after the link
  void check_bindings();  // throws when two resources share a binding point
  const Binding& declared(const std::string& name, bool buffer) const;
  void record(const Binding& binding, GLuint object) const;
  void check_work_group_fits() const;  // a compute program's group within the device's invocations

  GlName<delete_program> name_;
  std::string label_;
  std::vector<std::string> declared_;                  // uniforms the sources declare
  std::vector<std::pair<std::string, GLint>> active_;  // active uniforms and their locations
  std::vector<Binding> bindings_;                      // what the pass declared
  std::vector<GLenum> texture_queries_;                // per declaration: a texture's binding query
  mutable std::vector<GLuint> bound_;                  // per declaration: what bind() bound, 0: none
};

// Whether strict GL checks are on: LFD_GL_CHECKS=strict in the environment (set for every test
// by tests/CMakeLists.txt).
bool strict_gl_checks();

}  // namespace lfd::gpu
