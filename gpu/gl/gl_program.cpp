#include "gpu/gl/gl_program.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_flavour.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/gl_limits.hpp"
#include "gpu/gl/gl_work_groups.hpp"
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
                 const std::vector<std::string>& defines, std::vector<Binding> bindings)
    : label_(label), bindings_(std::move(bindings)) {
  // One source per pass: on OpenGL ES the assembly takes what differs (shader_source.hpp).
  const bool es = current_gl_is_es();
  std::string header = glsl_version_header(es);
  for (const std::string& d : defines) header += "#define " + d + "\n";
  const GLuint program = glCreateProgram();
  name_ = GlName<delete_program>(program);
  std::vector<GLuint> shaders;
  std::vector<std::string> texts;  // what the driver compiles after the header
  for (const auto& stage : stages) texts.push_back(es ? glsl_es_source(stage.second) : std::string(stage.second));
  for (size_t s = 0; s < stages.size(); ++s) {
    const auto& [type, source] = stages[s];
    const std::vector<std::string> files = shader_files(source);
    for (std::string& u : declared_uniforms(source)) declared_.push_back(std::move(u));
    // An embedded shader numbers its files in #line directives; other text starts at line 1.
    const std::string stage_header = files.empty() ? header + "#line 1\n" : header;
    const GLuint shader = glCreateShader(type);
    const char* parts[] = {stage_header.c_str(), texts[s].c_str()};
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
  for (size_t s = 0; s < stages.size(); ++s) dump_shader_variant(label, stages[s].first, header, texts[s].c_str());
  if (bindings_.empty()) return;
  const std::vector<ActiveResource> active = active_resources(program);
  verify_declaration(label_, bindings_, active);
  for (const Binding& b : bindings_) {
    GLenum query = 0;
    for (const ActiveResource& r : active)
      if (r.resource == b.resource && r.point == b.point) query = r.texture_binding;
    texture_queries_.push_back(query);
  }
  bound_.assign(bindings_.size(), 0);
}

void Program::list_uniforms() {
  GLint count = 0, longest = 0;
  glGetProgramiv(id(), GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(id(), GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  std::string name(size_t(std::max(longest, 1)), '\0');
  for (GLint i = 0; i < count; ++i) {
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(id(), GLuint(i), GLsizei(name.size()), &length, &size, &type, name.data());  // also ES
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

const Binding& Program::declared(const std::string& name, bool buffer) const {
  for (const Binding& b : bindings_) {
    if (b.name != name) continue;
    const bool is_buffer = b.resource == Resource::storage_buffer || b.resource == Resource::uniform_buffer;
    if (is_buffer != buffer)
      throw std::logic_error(fmt::format("pass '{}': '{}' is declared as {} {}, not bound as a {}", label_, name,
                                         resource_name(b.resource), b.point, buffer ? "buffer" : "texture"));
    return b;
  }
  throw std::logic_error(fmt::format("pass '{}': no binding '{}' is declared", label_, name));
}

void Program::record(const Binding& binding, GLuint object) const {
  bound_[size_t(&binding - bindings_.data())] = object;
}

void Program::bind(const std::string& name, const Buffer& buffer) const {
  const Binding& b = declared(name, true);
  glBindBufferBase(b.resource == Resource::storage_buffer ? GL_SHADER_STORAGE_BUFFER : GL_UNIFORM_BUFFER,
                   GLuint(b.point), buffer.id());
  record(b, buffer.id());
}

void Program::bind(const std::string& name, const Texture& texture) const {
  const Binding& b = declared(name, false);
  if (b.resource == Resource::texture) {
    bind_texture_unit(GLuint(b.point), texture.target(), texture.id());
  } else {
    const GLenum access = b.access == Access::read    ? GL_READ_ONLY
                          : b.access == Access::write ? GL_WRITE_ONLY
                                                      : GL_READ_WRITE;
    glBindImageTexture(GLuint(b.point), texture.id(), 0, texture.layers() ? GL_TRUE : GL_FALSE, 0, access,
                       texture.internal_format());
  }
  record(b, texture.id());
}

bool Program::declares(const std::string& name) const {
  for (const Binding& b : bindings_)
    if (b.name == name) return true;
  return false;
}

void Program::bind_texture_id(const std::string& name, GLuint texture) const {
  const Binding& b = declared(name, false);
  if (b.resource != Resource::texture)
    throw std::logic_error(fmt::format("pass '{}': '{}' is an image; bind it as a Texture", label_, name));
  bind_texture_unit(GLuint(b.point), GL_TEXTURE_2D, texture);  // lfd binds no foreign arrays
  record(b, texture);
}

void Program::check_bindings_before_use() const {
  if (bindings_.empty() || !strict_gl_checks()) return;
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  if (GLuint(current) != id())
    throw std::logic_error(fmt::format("pass '{}': used while program {} is current, not its own ({})", label_,
                                       current, id()));
  for (size_t i = 0; i < bindings_.size(); ++i) {
    const Binding& b = bindings_[i];
    const char* kind = resource_name(b.resource);
    if (bound_[i] == 0)
      throw std::logic_error(fmt::format("pass '{}': point {} ({} '{}') was never bound through the pass", label_,
                                         b.point, kind, b.name));
    const GLuint holds = bound_object(b, texture_queries_[i]);
    if (holds != bound_[i])
      throw std::logic_error(fmt::format("pass '{}': point {} ({} '{}') holds {} {}, not the one bound as '{}' ({})",
                                         label_, b.point, kind, b.name,
                                         b.resource == Resource::image || b.resource == Resource::texture ? "texture"
                                                                                                           : "buffer",
                                         holds, b.name, bound_[i]));
  }
}

void Program::dispatch(GLuint x, GLuint y, GLuint z) const {
  check_bindings_before_use();
  glDispatchCompute(x, y, z);
}

void Program::dispatch_1d(size_t items, int local_size) const {
  const size_t groups = (items + size_t(local_size) - 1) / size_t(local_size);
  if (groups == 0) return;
  // Beyond the 65535-group limit of one dimension, spread over y (gpu/gl/gl_work_groups.hpp).
  const WorkGroups spread = spread_work_groups(groups);
  dispatch(spread.x, spread.y, 1);
}

void Program::dispatch_groups(size_t groups, GLuint z) const {
  const WorkGroups spread = spread_work_groups(groups);
  if (spread.x == 0 || z == 0) return;
  dispatch(spread.x, spread.y, z);
}

void Program::dispatch_indirect(GLintptr offset) const {
  check_bindings_before_use();
  glDispatchComputeIndirect(offset);
}

void Program::draw_arrays(GLenum mode, GLint first, GLsizei count, GLsizei instances) const {
  check_bindings_before_use();
  if (instances == 1) glDrawArrays(mode, first, count);
  else glDrawArraysInstanced(mode, first, count, instances);
}

void Program::draw_arrays_indirect(GLenum mode, GLintptr offset) const {
  check_bindings_before_use();
  glDrawArraysIndirect(mode, reinterpret_cast<const void*>(offset));
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
