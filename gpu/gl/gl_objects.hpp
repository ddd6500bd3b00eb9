#pragma once
// Owning wrappers of OpenGL objects (direct state access, GL 4.5) and shader programs. Every
// renderer in gpu/ builds on these so object lifetimes, compile errors and GL errors are handled
// in one place. All need a current context. On an OpenGL ES 3.1 context (gl_flavour.hpp), which
// has no direct state access, each takes ES's form: the object bound to edit it, the binding it
// displaced put back (docs/gpu.md "OpenGL ES 3.1").
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_name.hpp"
#include "gpu/gl/gl_program.hpp"  // Program: shader programs, beside the wrappers of GL objects

namespace lfd::gpu {

// A buffer object of fixed size (glNamedBufferStorage, dynamic storage so it can be updated).
// Sizes are counted in gpu_bytes_allocated() for the memory figures of the benchmark.
class Buffer {
 public:
  Buffer() = default;
  explicit Buffer(size_t bytes, const void* data = nullptr);
  Buffer(Buffer&& o) noexcept;
  Buffer& operator=(Buffer&& o) noexcept;
  ~Buffer();
  GLuint id() const { return name_.id(); }
  size_t bytes() const { return bytes_; }
  // Grows (reallocating, contents lost) when smaller than `bytes`.
  void ensure(size_t bytes);
  void upload(const void* data, size_t bytes, size_t offset = 0);
  void download(void* data, size_t bytes, size_t offset = 0) const;
  template <typename T>
  std::vector<T> download_as(size_t count) const {
    std::vector<T> out(count);
    download(out.data(), count * sizeof(T));
    return out;
  }
  void bind_storage(GLuint binding) const;  // GL_SHADER_STORAGE_BUFFER binding point

 private:
  GlName<delete_buffer> name_;
  size_t bytes_ = 0;
};

// A texture (2D or 2D array) with immutable storage of one internal format.
class Texture {
 public:
  Texture() = default;
  // layers == 0: GL_TEXTURE_2D, else GL_TEXTURE_2D_ARRAY with that many layers.
  Texture(GLenum internal_format, int width, int height, int layers = 0);
  Texture(Texture&& o) noexcept;
  Texture& operator=(Texture&& o) noexcept;
  ~Texture();
  GLuint id() const { return name_.id(); }
  GLenum target() const { return layers_ ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D; }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }
  GLenum internal_format() const { return format_; }
  size_t bytes() const { return bytes_; }
  // Filtering and clamp-to-edge wrapping.
  void set_filter(GLenum min_mag) const;

 private:
  GlName<delete_texture> name_;
  GLenum format_ = 0;
  int width_ = 0, height_ = 0, layers_ = 0;
  size_t bytes_ = 0;
};

// Bytes per texel of the internal formats lfd uses (RGBA8, RGBA16F, RGBA32F, R32F, RG32F, ...).
size_t bytes_per_texel(GLenum internal_format);
// The GLSL image format qualifier of an RGBA8, RGBA16F or RGBA32F texture, for a compute pass
// that writes it with imageStore; std::logic_error naming `what` for another format.
const char* image_format_qualifier(GLenum internal_format, const char* what);

// Bytes of buffers and textures alive now and the most since reset_gpu_peak().
size_t gpu_bytes_allocated();
size_t gpu_bytes_peak();
void reset_gpu_peak();

// A framebuffer with colour attachments (a texture or all layers of an array texture).
class Framebuffer {
 public:
  Framebuffer();
  GLuint id() const { return name_.id(); }
  // Attaches `texture` (every layer of an array: layered rendering) at GL_COLOR_ATTACHMENT0+i.
  void attach(int index, const Texture& texture) const;
  // Sets the draw buffers to attachments 0..count-1 and throws if incomplete.
  void finish(int count) const;

 private:
  GlName<delete_framebuffer> name_;
};

// A sampler object: filtering and wrapping for texture(), set once (glSamplerParameter*).
class Sampler {
 public:
  Sampler();
  GLuint id() const { return name_.id(); }

 private:
  GlName<delete_sampler> name_;
};

class VertexArray {
 public:
  VertexArray();
  GLuint id() const { return name_.id(); }

 private:
  GlName<delete_vertex_array> name_;
};

// The 2D image of a texture (level 0; one layer of an array), RGBA float, rows bottom-up
// (glGetTextureSubImage; ES: glReadPixels through a framebuffer, float formats need
// EXT_color_buffer_float there).
std::vector<float> read_texture_rgba(const Texture& texture, int layer = 0);

// Binds texture `texture` of `target` to texture unit `unit` (glBindTextureUnit; ES: the unit
// made active and the texture bound there).
void bind_texture_unit(GLuint unit, GLenum target, GLuint texture);
// Writes a rectangle of level 0 of a 2D texture with the current unpack state
// (glTextureSubImage2D; ES: glTexSubImage2D with the texture bound for the call).
void upload_texture_2d(const Texture& texture, int x, int y, int width, int height, GLenum format, GLenum type,
                       const void* pixels);
// Sets every texel of level 0 of a 2D colour-renderable texture to `rgba` (glClearTexImage; ES:
// cleared as a framebuffer's attachment, the scissor test off).
void clear_texture(const Texture& texture, const float rgba[4]);

}  // namespace lfd::gpu
