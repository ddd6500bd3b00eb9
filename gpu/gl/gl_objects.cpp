#include "gpu/gl/gl_objects.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_fault.hpp"
#include "gpu/gl/gl_flavour.hpp"

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

// OpenGL ES has no direct state access: an object is bound to be edited. These keep what was
// bound before and put it back, so a pass's bindings stay what it set.
class KeepTextureBinding {
 public:
  KeepTextureBinding(GLenum target, GLuint texture) : target_(target) {
    glGetIntegerv(target == GL_TEXTURE_2D_ARRAY ? GL_TEXTURE_BINDING_2D_ARRAY : GL_TEXTURE_BINDING_2D, &previous_);
    glBindTexture(target, texture);
  }
  ~KeepTextureBinding() { glBindTexture(target_, GLuint(previous_)); }
  KeepTextureBinding(const KeepTextureBinding&) = delete;
  KeepTextureBinding& operator=(const KeepTextureBinding&) = delete;

 private:
  GLenum target_;
  GLint previous_ = 0;
};

class KeepFramebufferBinding {
 public:
  explicit KeepFramebufferBinding(GLuint framebuffer) {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  }
  ~KeepFramebufferBinding() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_));
  }
  KeepFramebufferBinding(const KeepFramebufferBinding&) = delete;
  KeepFramebufferBinding& operator=(const KeepFramebufferBinding&) = delete;

 private:
  GLint draw_ = 0, read_ = 0;
};

// Attaches level 0 of `texture` (`layer` of an array, or every layer when `layer` < 0) to the
// framebuffer bound at GL_FRAMEBUFFER, on ES.
void attach_es(GLenum attachment, const Texture& texture, int layer) {
  if (!texture.layers()) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture.id(), 0);
  } else if (layer >= 0) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, attachment, texture.id(), 0, layer);
  } else {
    if (epoxy_gl_version() < 32)
      throw std::logic_error("layered rendering into an array texture needs OpenGL 4.5 or OpenGL ES 3.2");
    glFramebufferTexture(GL_FRAMEBUFFER, attachment, texture.id(), 0);
  }
}

bool normalized_8bit(GLenum format) { return format == GL_RGBA8 || format == GL_R8 || format == GL_RG8; }

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
  if (current_gl_is_es()) {
    glGenBuffers(1, &id);
    name_ = GlName<delete_buffer>(id);
    glBindBuffer(GL_COPY_WRITE_BUFFER, id);  // a binding no pass reads
    glBufferData(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  } else {
    glCreateBuffers(1, &id);
    name_ = GlName<delete_buffer>(id);
    glNamedBufferStorage(id, GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  if (glGetError() == GL_OUT_OF_MEMORY || gl_fault(GlFault::kOutOfMemory))
    throw GlPathFailed(fmt::format("GPU out of memory allocating a {:.1f} MiB buffer ({:.1f} MiB held already)",
                                   bytes / 1048576.0, gpu_bytes_allocated() / 1048576.0));
  bytes_ = bytes;
  count_alloc(bytes_);
}

void Buffer::upload(const void* data, size_t bytes, size_t offset) {
  if (!data || !bytes) return;
  if (offset + bytes > bytes_) throw std::logic_error("Buffer::upload past the end");
  if (current_gl_is_es()) {
    glBindBuffer(GL_COPY_WRITE_BUFFER, id());
    glBufferSubData(GL_COPY_WRITE_BUFFER, GLintptr(offset), GLsizeiptr(bytes), data);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    return;
  }
  glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::download(void* data, size_t bytes, size_t offset) const {
  if (!bytes) return;
  if (offset + bytes > bytes_) throw std::logic_error("Buffer::download past the end");
  // What shaders wrote is read back only after this barrier; a download waits anyway.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // also ES: it covers mapping
  if (current_gl_is_es()) {  // ES reads a buffer by mapping it
    glBindBuffer(GL_COPY_READ_BUFFER, id());
    const void* mapped = glMapBufferRange(GL_COPY_READ_BUFFER, GLintptr(offset), GLsizeiptr(bytes), GL_MAP_READ_BIT);
    if (mapped) std::memcpy(data, mapped, bytes);
    glUnmapBuffer(GL_COPY_READ_BUFFER);
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    if (!mapped) check_gl("mapping a buffer to read it");
    return;
  }
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
    case GL_RGB8: return 3;
    default: return 16;
  }
}

Texture::Texture(GLenum internal_format, int width, int height, int layers)
    : format_(internal_format), width_(width), height_(height), layers_(layers) {
  GLuint id = 0;
  if (current_gl_is_es()) {
    glGenTextures(1, &id);
    name_ = GlName<delete_texture>(id);
    KeepTextureBinding bound(target(), id);
    if (layers)
      glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, internal_format, width, height, layers);
    else
      glTexStorage2D(GL_TEXTURE_2D, 1, internal_format, width, height);
  } else {
    glCreateTextures(layers ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, 1, &id);
    name_ = GlName<delete_texture>(id);
    if (layers)
      glTextureStorage3D(id, 1, internal_format, width, height, layers);
    else
      glTextureStorage2D(id, 1, internal_format, width, height);
  }
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
  if (current_gl_is_es()) {
    KeepTextureBinding bound(target(), id());
    glTexParameteri(target(), GL_TEXTURE_MIN_FILTER, GLint(min_mag));
    glTexParameteri(target(), GL_TEXTURE_MAG_FILTER, GLint(min_mag));
    glTexParameteri(target(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return;
  }
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(min_mag));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(min_mag));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

std::vector<float> read_texture_rgba(const Texture& texture, int layer) {
  const size_t count = size_t(texture.width()) * texture.height() * 4;
  std::vector<float> out(count);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // image stores before the read-back
  if (current_gl_is_es()) {  // no glGetTexImage: the texture read as a framebuffer
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);     // ... which glReadPixels reads as a framebuffer
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    const GlName<delete_framebuffer> owned(framebuffer);
    KeepFramebufferBinding bound(framebuffer);
    attach_es(GL_COLOR_ATTACHMENT0, texture, texture.layers() ? layer : -1);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    if (normalized_8bit(texture.internal_format())) {  // ES reads these as bytes only
      std::vector<uint8_t> bytes(count);
      glReadPixels(0, 0, texture.width(), texture.height(), GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
      for (size_t i = 0; i < count; ++i) out[i] = bytes[i] / 255.f;
    } else {
      glReadPixels(0, 0, texture.width(), texture.height(), GL_RGBA, GL_FLOAT, out.data());
    }
    check_gl("reading a texture back");
    return out;
  }
  glGetTextureSubImage(texture.id(), 0, 0, 0, texture.layers() ? layer : 0, texture.width(),
                       texture.height(), 1, GL_RGBA, GL_FLOAT, GLsizei(count * sizeof(float)),
                       out.data());
  check_gl("reading a texture back");
  return out;
}

// ---- Framebuffer, VertexArray ----

Framebuffer::Framebuffer() {
  GLuint id = 0;
  if (current_gl_is_es()) {
    glGenFramebuffers(1, &id);
    name_ = GlName<delete_framebuffer>(id);
    KeepFramebufferBinding bound(id);  // a generated name is a framebuffer once bound
    return;
  }
  glCreateFramebuffers(1, &id);
  name_ = GlName<delete_framebuffer>(id);
}

void Framebuffer::attach(int index, const Texture& texture) const {
  if (current_gl_is_es()) {
    KeepFramebufferBinding bound(id());
    attach_es(GLenum(GL_COLOR_ATTACHMENT0 + index), texture, -1);
    return;
  }
  glNamedFramebufferTexture(id(), GLenum(GL_COLOR_ATTACHMENT0 + index), texture.id(), 0);
}

void Framebuffer::finish(int count) const {
  std::vector<GLenum> buffers;
  for (int i = 0; i < count; ++i) buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  GLenum status = 0;
  if (current_gl_is_es()) {
    KeepFramebufferBinding bound(id());
    glDrawBuffers(GLsizei(buffers.size()), buffers.data());
    status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  } else {
    glNamedFramebufferDrawBuffers(id(), GLsizei(buffers.size()), buffers.data());
    status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  }
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(fmt::format("framebuffer incomplete (0x{:x})", status));
}

Sampler::Sampler() {
  GLuint id = 0;
  if (current_gl_is_es()) glGenSamplers(1, &id);  // a sampler name is an object at once
  else glCreateSamplers(1, &id);
  name_ = GlName<delete_sampler>(id);
}

VertexArray::VertexArray() {
  GLuint id = 0;
  if (current_gl_is_es()) glGenVertexArrays(1, &id);  // becomes one when first bound (a draw binds it)
  else glCreateVertexArrays(1, &id);
  name_ = GlName<delete_vertex_array>(id);
}

void bind_texture_unit(GLuint unit, GLenum target, GLuint texture) {
  if (!current_gl_is_es()) return glBindTextureUnit(unit, texture);
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(target, texture);
  glActiveTexture(GL_TEXTURE0);
}

void upload_texture_2d(const Texture& texture, int x, int y, int width, int height, GLenum format, GLenum type,
                       const void* pixels) {
  if (!current_gl_is_es())
    return glTextureSubImage2D(texture.id(), 0, x, y, width, height, format, type, pixels);
  KeepTextureBinding bound(GL_TEXTURE_2D, texture.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, width, height, format, type, pixels);
}

void clear_texture(const Texture& texture, const float rgba[4]) {
  if (!current_gl_is_es()) return glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, rgba);
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  const GlName<delete_framebuffer> owned(framebuffer);
  KeepFramebufferBinding bound(framebuffer);
  attach_es(GL_COLOR_ATTACHMENT0, texture, -1);
  const GLenum draw = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &draw);
  const bool scissor = glIsEnabled(GL_SCISSOR_TEST);
  glDisable(GL_SCISSOR_TEST);
  glClearBufferfv(GL_COLOR, 0, rgba);
  if (scissor) glEnable(GL_SCISSOR_TEST);
  check_gl("clearing a texture");
}

}  // namespace lfd::gpu
