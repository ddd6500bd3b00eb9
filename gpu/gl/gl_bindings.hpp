#pragma once
// What a pass reads and writes at which binding point, declared with its program (docs/gpu.md
// "Binding points"). Passes share binding points by convention (a contract header's
// LFD_IO_INT(k...Binding, N)); the declaration makes the convention checked:
// - at link time the program's own active resources (storage and uniform blocks, image and
//   sampler uniforms) must match the declaration point for point (std::logic_error otherwise);
// - the pass binds by declared name (Program::bind), which records the object bound;
// - under strict GL checks every Program dispatch or draw asks GL what each declared point holds
//   and throws when it is not what the pass bound (a helper that rebound a shared point in
//   between, or a point the pass never bound). Without strict checks nothing is asked: a frame
//   never waits on a glGet (docs/gpu.md "A frame that never waits").
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>

namespace lfd::gpu {

// Each kind has its own namespace of points in GL: storage buffer 0, uniform buffer 0, image
// unit 0 and texture unit 0 are four different points.
enum class Resource { storage_buffer, uniform_buffer, image, texture };
enum class Access { read, write, read_write };

struct Binding {
  std::string name;  // the pass's name for it, as bind() takes it and errors print it
  Resource resource;
  Access access;  // images: bound with this access; buffers and textures: documentation
  int point;      // from the contract header (gpu/*/shaders/*_io.h)
};

// Short spellings for the declaration lists of the passes.
inline Binding storage_buffer(std::string name, int point, Access access) {
  return {std::move(name), Resource::storage_buffer, access, point};
}
inline Binding uniform_buffer(std::string name, int point) {
  return {std::move(name), Resource::uniform_buffer, Access::read, point};
}
inline Binding image(std::string name, int point, Access access) {
  return {std::move(name), Resource::image, access, point};
}
inline Binding texture(std::string name, int point) { return {std::move(name), Resource::texture, Access::read, point}; }

const char* resource_name(Resource resource);  // "storage buffer", "uniform buffer", "image", "texture"

// A resource the linked program uses at a point, found by program interface queries.
struct ActiveResource {
  Resource resource;
  int point;
  std::string shader_name;   // the block's or uniform's name in GLSL
  GLenum texture_binding = 0;  // textures: GL_TEXTURE_BINDING_* of the sampler's target
};
std::vector<ActiveResource> active_resources(GLuint program);

// Throws std::logic_error naming `label` and the point when `declared` and the program's active
// resources disagree: an active resource at a point not declared there, a declared point the
// program does not use, or two declarations of one name or one point.
void verify_declaration(const std::string& label, const std::vector<Binding>& declared,
                        const std::vector<ActiveResource>& active);

// The GL object a point holds now (glGetIntegeri_v; textures through the active unit, restored).
GLuint bound_object(const Binding& binding, GLenum texture_binding);

}  // namespace lfd::gpu
