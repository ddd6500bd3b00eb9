#pragma once
// A texture read back to the CPU without the CPU waiting for the GPU: glGetTextureImage into a
// pixel buffer object (a GPU copy; into client memory it would wait), a fence behind it, and the
// fence polled with glClientWaitSync timeout 0 on later frames; the bytes are then read from the
// buffer's persistent mapping (gpu/gl/gl_mapped_buffer.hpp). The viewer's "seen from" preview reads
// the panel this way (docs/gpu.md "A frame that never waits").
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "gpu/gl/gl_mapped_buffer.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "util/image.hpp"

namespace lfd::gpu {

class AsyncTextureReadback {
 public:
  AsyncTextureReadback() = default;
  AsyncTextureReadback(AsyncTextureReadback&& o) noexcept
      : pixels_(std::move(o.pixels_)), fence_(std::exchange(o.fence_, nullptr)), width_(o.width_), height_(o.height_) {}
  AsyncTextureReadback& operator=(AsyncTextureReadback&&) = delete;
  ~AsyncTextureReadback();

  // Starts the copy of `texture` (level 0 of a 2D texture) as RGBA8 unless one is under way
  // (returns false then). The pixel buffer is made or grown here, not per frame.
  bool start(const Texture& texture);
  bool busy() const { return fence_ != nullptr; }
  // The texels (RGBA8, rows top-down: row 0 the image's top) once the copy is done, else nullopt;
  // never waits.
  std::optional<Image8> poll();

 private:
  MappedReadBuffer pixels_;
  GLsync fence_ = nullptr;
  int width_ = 0, height_ = 0;
};

}  // namespace lfd::gpu
