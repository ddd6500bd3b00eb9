#include "gpu/gl/gl_mapped_buffer.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace lfd::gpu {

MappedReadBuffer::MappedReadBuffer(size_t bytes) : bytes_(bytes) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  name_ = GlName<delete_buffer>(id);
  const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  glNamedBufferStorage(id, GLsizeiptr(bytes), nullptr, flags);
  // At creation the buffer holds nothing the GPU wrote: mapping it waits for nothing.
  mapped_ = static_cast<const std::byte*>(glMapNamedBufferRange(id, 0, GLsizeiptr(bytes), flags));
  if (!mapped_)
    throw std::runtime_error(fmt::format("GL: a {:.1f} MiB read-back buffer cannot be mapped (0x{:x})",
                                         double(bytes) / 1048576.0, glGetError()));
}

MappedReadBuffer::~MappedReadBuffer() {
  if (name_ && mapped_) glUnmapNamedBuffer(name_.id());
}

}  // namespace lfd::gpu
