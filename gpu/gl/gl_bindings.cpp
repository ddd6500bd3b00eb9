#include "gpu/gl/gl_bindings.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace lfd::gpu {
namespace {

// The opaque uniform types lfd's shaders use, with the texture binding a sampler's target is
// queried by. Float, int and uint variants; images have no target to query (GL_IMAGE_BINDING_NAME).
struct OpaqueType {
  GLenum type;
  Resource resource;
  GLenum texture_binding;
};
constexpr OpaqueType kOpaqueTypes[] = {
    {GL_SAMPLER_2D, Resource::texture, GL_TEXTURE_BINDING_2D},
    {GL_INT_SAMPLER_2D, Resource::texture, GL_TEXTURE_BINDING_2D},
    {GL_UNSIGNED_INT_SAMPLER_2D, Resource::texture, GL_TEXTURE_BINDING_2D},
    {GL_SAMPLER_2D_ARRAY, Resource::texture, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_INT_SAMPLER_2D_ARRAY, Resource::texture, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_UNSIGNED_INT_SAMPLER_2D_ARRAY, Resource::texture, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_SAMPLER_3D, Resource::texture, GL_TEXTURE_BINDING_3D},
    {GL_SAMPLER_1D, Resource::texture, GL_TEXTURE_BINDING_1D},
    {GL_SAMPLER_CUBE, Resource::texture, GL_TEXTURE_BINDING_CUBE_MAP},
    {GL_SAMPLER_BUFFER, Resource::texture, GL_TEXTURE_BINDING_BUFFER},
    {GL_SAMPLER_2D_RECT, Resource::texture, GL_TEXTURE_BINDING_RECTANGLE},
    {GL_IMAGE_2D, Resource::image, 0},
    {GL_INT_IMAGE_2D, Resource::image, 0},
    {GL_UNSIGNED_INT_IMAGE_2D, Resource::image, 0},
    {GL_IMAGE_2D_ARRAY, Resource::image, 0},
    {GL_INT_IMAGE_2D_ARRAY, Resource::image, 0},
    {GL_UNSIGNED_INT_IMAGE_2D_ARRAY, Resource::image, 0},
    {GL_IMAGE_3D, Resource::image, 0},
    {GL_IMAGE_1D, Resource::image, 0},
    {GL_IMAGE_BUFFER, Resource::image, 0},
};

const OpaqueType* opaque_type(GLenum type) {
  for (const OpaqueType& t : kOpaqueTypes)
    if (t.type == type) return &t;
  return nullptr;
}

std::string resource_name_of(GLuint program, GLenum interface, GLuint index) {
  char name[256] = {};
  glGetProgramResourceName(program, interface, index, sizeof name, nullptr, name);
  return name;
}

void add_blocks(GLuint program, GLenum interface, Resource resource, std::vector<ActiveResource>& out) {
  GLint count = 0;
  glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    const GLenum property = GL_BUFFER_BINDING;
    GLint point = -1;
    glGetProgramResourceiv(program, interface, GLuint(i), 1, &property, 1, nullptr, &point);
    out.push_back({resource, point, resource_name_of(program, interface, GLuint(i))});
  }
}

void add_opaque_uniforms(GLuint program, std::vector<ActiveResource>& out) {
  GLint count = 0;
  glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    const GLenum properties[] = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE};
    GLint values[3] = {};
    glGetProgramResourceiv(program, GL_UNIFORM, GLuint(i), 3, properties, 3, nullptr, values);
    const OpaqueType* type = opaque_type(GLenum(values[0]));
    if (type == nullptr || values[1] < 0) continue;
    const std::string name = resource_name_of(program, GL_UNIFORM, GLuint(i));
    // An opaque uniform's value is its unit; an array has one per element.
    for (GLint e = 0; e < values[2]; ++e) {
      GLint unit = -1;
      glGetUniformiv(program, values[1] + e, &unit);
      out.push_back({type->resource, unit, name, type->texture_binding});
    }
  }
}

GLenum buffer_binding_query(Resource resource) {
  return resource == Resource::storage_buffer ? GL_SHADER_STORAGE_BUFFER_BINDING : GL_UNIFORM_BUFFER_BINDING;
}

}  // namespace


const char* resource_name(Resource resource) {
  switch (resource) {
    case Resource::storage_buffer: return "storage buffer";
    case Resource::uniform_buffer: return "uniform buffer";
    case Resource::image: return "image";
    case Resource::texture: return "texture";
  }
  return "?";
}

std::vector<ActiveResource> active_resources(GLuint program) {
  std::vector<ActiveResource> out;
  add_blocks(program, GL_SHADER_STORAGE_BLOCK, Resource::storage_buffer, out);
  add_blocks(program, GL_UNIFORM_BLOCK, Resource::uniform_buffer, out);
  add_opaque_uniforms(program, out);
  return out;
}

void verify_declaration(const std::string& label, const std::vector<Binding>& declared,
                        const std::vector<ActiveResource>& active) {
  for (size_t i = 0; i < declared.size(); ++i)
    for (size_t j = 0; j < i; ++j) {
      const Binding& a = declared[j];
      const Binding& b = declared[i];
      if (a.name == b.name)
        throw std::logic_error(fmt::format("program '{}': '{}' is declared twice (points {} and {})", label, a.name,
                                           a.point, b.point));
      if (a.resource == b.resource && a.point == b.point)
        throw std::logic_error(fmt::format("program '{}': point {} ({}) is declared as both '{}' and '{}'", label,
                                           a.point, resource_name(a.resource), a.name, b.name));
    }
  for (const ActiveResource& r : active) {
    bool found = false;
    for (const Binding& b : declared) found = found || (b.resource == r.resource && b.point == r.point);
    if (!found)
      throw std::logic_error(fmt::format("program '{}': point {} ({} '{}' in the shader) is not declared", label,
                                         r.point, resource_name(r.resource), r.shader_name));
  }
  for (const Binding& b : declared) {
    bool found = false;
    for (const ActiveResource& r : active) found = found || (b.resource == r.resource && b.point == r.point);
    if (!found)
      throw std::logic_error(fmt::format("program '{}': point {} ({} '{}') is declared but the shader uses no {} there",
                                         label, b.point, resource_name(b.resource), b.name,
                                         resource_name(b.resource)));
  }
}

GLuint bound_object(const Binding& binding, GLenum texture_binding) {
  GLint name = 0;
  switch (binding.resource) {
    case Resource::storage_buffer:
    case Resource::uniform_buffer:
      glGetIntegeri_v(buffer_binding_query(binding.resource), GLuint(binding.point), &name);
      break;
    case Resource::image:
      glGetIntegeri_v(GL_IMAGE_BINDING_NAME, GLuint(binding.point), &name);
      break;
    case Resource::texture: {
      GLint active = 0;
      glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
      glActiveTexture(GLenum(GL_TEXTURE0 + binding.point));
      glGetIntegerv(texture_binding, &name);
      glActiveTexture(GLenum(active));
      break;
    }
  }
  return GLuint(name);
}

}  // namespace lfd::gpu
