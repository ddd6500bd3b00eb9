#pragma once
// A buffer the GPU writes and the CPU reads through one mapping made at creation
// (GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT, GL 4.4): the frame loop reads GPU results
// without glMapBuffer or glGetBufferSubData, both of which wait for the GPU. The CPU may read a
// region only after a fence placed behind the GPU's write has signalled (gpu/gl/gl_frame_ring.hpp,
// gpu/gl/gl_async_readback.hpp).
#include <cstddef>

#include "gpu/gl/gl_objects.hpp"

namespace lfd::gpu {

class MappedReadBuffer {
 public:
  MappedReadBuffer() = default;
  explicit MappedReadBuffer(size_t bytes);
  MappedReadBuffer(MappedReadBuffer&&) noexcept = default;
  MappedReadBuffer& operator=(MappedReadBuffer&&) noexcept = default;
  ~MappedReadBuffer();  // unmaps (deleting the buffer does too; explicit for clarity)
  GLuint id() const { return name_.id(); }
  size_t bytes() const { return bytes_; }
  const std::byte* data() const { return mapped_; }

 private:
  GlName<delete_buffer> name_;
  size_t bytes_ = 0;
  const std::byte* mapped_ = nullptr;
};

}  // namespace lfd::gpu
