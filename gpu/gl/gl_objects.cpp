#include "gpu/gl/gl_objects.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_fault.hpp"

namespace lfd::gpu {
namespace {

std::atomic<size_t> g_bytes{0};
std::atomic<size_t> g_peak{0};

void count_alloc(size_t bytes) {
  const size_t now = g_bytes += bytes;
  size_t peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
  }
}
void count_free(size_t bytes) { g_bytes -= bytes; }

const char* gl_error_name(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error";
  }
}

}  // namespace

void check_gl(const char* what) {
  const GLenum e = glGetError();
  // Under strict checks the debug output may have seen an error glGetError no longer holds.
  if (const std::string debug = take_gl_debug_error(); !debug.empty()) {
    while (glGetError() != GL_NO_ERROR) {
    }
    throw std::runtime_error(fmt::format("GL error after {}: {}", what, debug));
  }
  if (e == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  throw std::runtime_error(fmt::format("{} (0x{:x}) after {}", gl_error_name(e), e, what));
}

void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
void delete_program(GLuint id) { glDeleteProgram(id); }
void delete_query(GLuint id) { glDeleteQueries(1, &id); }
void delete_sampler(GLuint id) { glDeleteSamplers(1, &id); }

size_t gpu_bytes_allocated() { return g_bytes.load(); }
size_t gpu_bytes_peak() { return g_peak.load(); }
void reset_gpu_peak() { g_peak = g_bytes.load(); }

// ---- Buffer ----

Buffer::Buffer(size_t bytes, const void* data) {
  ensure(std::max<size_t>(bytes, 4));
  if (data && bytes) upload(data, bytes);
}

Buffer::Buffer(Buffer&& o) noexcept : name_(std::move(o.name_)), bytes_(std::exchange(o.bytes_, 0)) {}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    count_free(bytes_);
    name_ = std::move(o.name_);
    bytes_ = std::exchange(o.bytes_, 0);
  }
  return *this;
}

Buffer::~Buffer() { count_free(bytes_); }

void Buffer::ensure(size_t bytes) {
  if (name_ && bytes <= bytes_) return;
  count_free(bytes_);
  name_.reset();
  bytes_ = 0;
  GLuint id = 0;
  glCreateBuffers(1, &id);
  name_ = GlName<delete_buffer>(id);
  glNamedBufferStorage(id, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
  if (glGetError() == GL_OUT_OF_MEMORY || gl_fault(GlFault::kOutOfMemory))
    throw GlPathFailed(fmt::format("GPU out of memory allocating a {:.1f} MiB buffer ({:.1f} MiB held already)",
                                   bytes / 1048576.0, gpu_bytes_allocated() / 1048576.0));
  bytes_ = bytes;
  count_alloc(bytes_);
}

void Buffer::upload(const void* data, size_t bytes, size_t offset) {
  if (!data || !bytes) return;
  if (offset + bytes > bytes_) throw std::logic_error("Buffer::upload past the end");
  glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::download(void* data, size_t bytes, size_t offset) const {
  if (!bytes) return;
  if (offset + bytes > bytes_) throw std::logic_error("Buffer::download past the end");
  // What shaders wrote is read back only after this barrier; a download waits anyway.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::bind_storage(GLuint binding) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, id());
}

// ---- Texture ----

const char* image_format_qualifier(GLenum internal_format, const char* what) {
  switch (internal_format) {
    case GL_RGBA8: return "rgba8";
    case GL_RGBA16F: return "rgba16f";
    case GL_RGBA32F: return "rgba32f";
    default: throw std::logic_error(std::string(what) + ": use GL_RGBA8, GL_RGBA16F or GL_RGBA32F");
  }
}

size_t bytes_per_texel(GLenum f) {
  switch (f) {
    case GL_RGBA8: case GL_R32F: case GL_R32UI: case GL_RGBA8UI: case GL_RG16F: return 4;
    case GL_RGBA16F: case GL_RG32F: return 8;
    case GL_RGBA32F: return 16;
    case GL_R8: return 1;
    case GL_R16F: case GL_RG8: return 2;
    default: return 16;
  }
}

Texture::Texture(GLenum internal_format, int width, int height, int layers)
    : format_(internal_format), width_(width), height_(height), layers_(layers) {
  GLuint id = 0;
  glCreateTextures(layers ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, 1, &id);
  name_ = GlName<delete_texture>(id);
  if (layers)
    glTextureStorage3D(id, 1, internal_format, width, height, layers);
  else
    glTextureStorage2D(id, 1, internal_format, width, height);
  GLenum e = glGetError();
  if (e == GL_NO_ERROR && gl_fault(GlFault::kOutOfMemory)) e = GL_OUT_OF_MEMORY;
  if (e != GL_NO_ERROR)
    throw GlPathFailed(fmt::format(
        "GPU could not allocate a {}x{}x{} texture ({:.1f} MiB): {}", width, height,
        std::max(layers, 1), double(width) * height * std::max(layers, 1) * bytes_per_texel(internal_format) / 1048576.0,
        gl_error_name(e)));
  bytes_ = size_t(width) * height * std::max(layers, 1) * bytes_per_texel(internal_format);
  count_alloc(bytes_);
  set_filter(GL_NEAREST);
}

Texture::Texture(Texture&& o) noexcept
    : name_(std::move(o.name_)), format_(o.format_), width_(o.width_), height_(o.height_),
      layers_(o.layers_), bytes_(std::exchange(o.bytes_, 0)) {}

Texture& Texture::operator=(Texture&& o) noexcept {
  if (this != &o) {
    count_free(bytes_);
    name_ = std::move(o.name_);
    format_ = o.format_;
    width_ = o.width_;
    height_ = o.height_;
    layers_ = o.layers_;
    bytes_ = std::exchange(o.bytes_, 0);
  }
  return *this;
}

Texture::~Texture() { count_free(bytes_); }

void Texture::set_filter(GLenum min_mag) const {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(min_mag));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(min_mag));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

std::vector<float> read_texture_rgba(const Texture& texture, int layer) {
  const size_t count = size_t(texture.width()) * texture.height() * 4;
  std::vector<float> out(count);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // image stores before the read-back
  glGetTextureSubImage(texture.id(), 0, 0, 0, texture.layers() ? layer : 0, texture.width(),
                       texture.height(), 1, GL_RGBA, GL_FLOAT, GLsizei(count * sizeof(float)),
                       out.data());
  check_gl("reading a texture back");
  return out;
}

// ---- Framebuffer, VertexArray ----

Framebuffer::Framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  name_ = GlName<delete_framebuffer>(id);
}

void Framebuffer::attach(int index, const Texture& texture) const {
  glNamedFramebufferTexture(id(), GLenum(GL_COLOR_ATTACHMENT0 + index), texture.id(), 0);
}

void Framebuffer::finish(int count) const {
  std::vector<GLenum> buffers;
  for (int i = 0; i < count; ++i) buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  glNamedFramebufferDrawBuffers(id(), GLsizei(buffers.size()), buffers.data());
  const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(fmt::format("framebuffer incomplete (0x{:x})", status));
}

Sampler::Sampler() {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  name_ = GlName<delete_sampler>(id);
}

VertexArray::VertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  name_ = GlName<delete_vertex_array>(id);
}

}  // namespace lfd::gpu
