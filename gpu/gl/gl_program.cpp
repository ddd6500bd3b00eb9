#include "gpu/gl/gl_program.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_limits.hpp"
#include "gpu/gl/shader_dump.hpp"
#include "gpu/gl/shader_source.hpp"

namespace lfd::gpu {
namespace {


std::string info_log(GLuint object, bool program) {
  GLint length = 0;
  program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(size_t(std::max(length, 1)), '\0');
  program ? glGetProgramInfoLog(object, length, nullptr, log.data())
          : glGetShaderInfoLog(object, length, nullptr, log.data());
  return std::string(log.c_str());
}

// The resources whose binding points a program's C++ side sets, each kind its own namespace of
// points (an SSBO and a UBO may both use 0).
struct BindingKind {
  GLenum interface;
  const char* what;
};
constexpr BindingKind kBindingKinds[] = {{GL_SHADER_STORAGE_BLOCK, "storage block"},
                                         {GL_UNIFORM_BLOCK, "uniform block"}};

}  // namespace


bool strict_gl_checks() {
  // Read each time (it is asked when a context is made and when a uniform is missing, not per
  // draw), so a test can turn the checks on for itself.
  const char* v = std::getenv("LFD_GL_CHECKS");
  return v != nullptr && std::strcmp(v, "strict") == 0;
}

Program::Program(const std::string& label, const std::vector<std::pair<GLenum, const char*>>& stages,
                 const std::vector<std::string>& defines)
    : label_(label) {
  std::string header = "#version 450 core\n";
  for (const std::string& d : defines) header += "#define " + d + "\n";
  const GLuint program = glCreateProgram();
  name_ = GlName<delete_program>(program);
  std::vector<GLuint> shaders;
  for (const auto& [type, source] : stages) {
    const std::vector<std::string> files = shader_files(source);
    for (std::string& u : declared_uniforms(source)) declared_.push_back(std::move(u));
    // An embedded shader numbers its files in #line directives; other text starts at line 1.
    const std::string stage_header = files.empty() ? header + "#line 1\n" : header;
    const GLuint shader = glCreateShader(type);
    const char* parts[] = {stage_header.c_str(), source};
    glShaderSource(shader, 2, parts, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = name_files_in_log(info_log(shader, false), files);
      glDeleteShader(shader);
      for (GLuint s : shaders) glDeleteShader(s);
      // The exception carries the log; the debug output's copy of the same error would fail the
      // next check_gl, in whatever pass (or test) comes next.
      take_gl_debug_error();
      throw std::runtime_error(fmt::format("shader '{}' does not compile: {}", label, log));
    }
    glAttachShader(program, shader);
    shaders.push_back(shader);
  }
  glLinkProgram(program);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    take_gl_debug_error();  // as for a compile error
    throw std::runtime_error(fmt::format("program '{}' does not link: {}", label, info_log(program, true)));
  }
  list_uniforms();
  check_bindings();
  if (std::any_of(stages.begin(), stages.end(), [](const auto& s) { return s.first == GL_COMPUTE_SHADER; }))
    check_work_group_fits();
  for (const auto& [type, source] : stages) dump_shader_variant(label, type, header, source);
}

void Program::list_uniforms() {
  GLint count = 0, longest = 0;
  glGetProgramiv(id(), GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(id(), GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  std::string name(size_t(std::max(longest, 1)), '\0');
  for (GLint i = 0; i < count; ++i) {
    GLsizei length = 0;
    glGetActiveUniformName(id(), GLuint(i), GLsizei(name.size()), &length, name.data());
    std::string n(name.data(), size_t(length));
    const GLint location = glGetUniformLocation(id(), n.c_str());
    if (location < 0) continue;  // in a uniform block: no location
    // An array is listed as "name[0]"; GLSL also accepts "name".
    if (n.size() > 3 && n.compare(n.size() - 3, 3, "[0]") == 0) active_.emplace_back(n.substr(0, n.size() - 3), location);
    active_.emplace_back(std::move(n), location);
  }
}

void Program::check_bindings() {
  for (const BindingKind& kind : kBindingKinds) {
    GLint count = 0;
    glGetProgramInterfaceiv(id(), kind.interface, GL_ACTIVE_RESOURCES, &count);
    std::vector<std::pair<GLint, std::string>> seen;
    for (GLint i = 0; i < count; ++i) {
      const GLenum property = GL_BUFFER_BINDING;
      GLint binding = -1;
      glGetProgramResourceiv(id(), kind.interface, GLuint(i), 1, &property, 1, nullptr, &binding);
      char block[256] = {};
      glGetProgramResourceName(id(), kind.interface, GLuint(i), sizeof block, nullptr, block);
      for (const auto& [b, other] : seen)
        if (b == binding)
          throw std::logic_error(fmt::format("program '{}': {}s {} and {} share binding {}", label_, kind.what,
                                             other, block, binding));
      seen.emplace_back(binding, block);
    }
  }
}

void Program::use() const { glUseProgram(id()); }

GLint Program::uniform(const char* name) const {
  for (const auto& [n, location] : active_)
    if (n == name) return location;
  if (std::find(declared_.begin(), declared_.end(), name) == declared_.end())
    throw std::logic_error(fmt::format("program '{}': no uniform '{}' in its sources", label_, name));
  if (strict_gl_checks())
    throw std::logic_error(fmt::format("program '{}': uniform '{}' is declared but unused (optimised away)", label_, name));
  return -1;
}

void Program::dispatch_1d(size_t items, int local_size) const {
  const size_t groups = (items + size_t(local_size) - 1) / size_t(local_size);
  if (groups == 0) return;
  // Beyond the 65535-group limit of one dimension, spread over y (shaders use gl_NumWorkGroups).
  const GLuint x = GLuint(std::min<size_t>(groups, 65535));
  const GLuint y = GLuint((groups + 65534) / 65535);
  glDispatchCompute(x, y, 1);
}

void Program::check_work_group_fits() const {
  GLint size[3] = {1, 1, 1};
  glGetProgramiv(id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  const long long invocations = 1ll * size[0] * size[1] * size[2];
  const GlLimits limits = gl_limits();
  if (limits.invocations > 0 && invocations > limits.invocations)
    throw std::runtime_error(fmt::format("program '{}': a work group of {}x{}x{} invocations exceeds this GPU's {} "
                                         "(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS)",
                                         label_, size[0], size[1], size[2], limits.invocations));
}

}  // namespace lfd::gpu
