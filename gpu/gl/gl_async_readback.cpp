#include "gpu/gl/gl_async_readback.hpp"

#include <algorithm>

namespace lfd::gpu {

AsyncTextureReadback::~AsyncTextureReadback() {
  if (fence_) glDeleteSync(fence_);
}

bool AsyncTextureReadback::start(const Texture& texture) {
  if (fence_) return false;
  width_ = texture.width();
  height_ = texture.height();
  const size_t bytes = size_t(width_) * size_t(height_) * 4;
  if (pixels_.bytes() < bytes) pixels_ = MappedReadBuffer(bytes);
  // Image stores into the texture reach the copy only after this barrier.
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, pixels_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  // With a pack buffer bound the pointer is an offset into it: a GPU copy, no wait.
  glGetTextureImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bytes), nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();  // the copy and the fence go to the GPU now, not with the next frame's commands
  check_gl("starting a texture read-back into a pixel buffer");
  return true;
}

std::optional<Image8> AsyncTextureReadback::poll() {
  if (!fence_) return std::nullopt;
  const GLenum status = glClientWaitSync(fence_, 0, 0);  // a poll: timeout 0
  if (status != GL_ALREADY_SIGNALED && status != GL_CONDITION_SATISFIED) return std::nullopt;
  glDeleteSync(fence_);
  fence_ = nullptr;
  Image8 image(width_, height_, 4);
  const size_t row = size_t(width_) * 4;
  const std::byte* texels = pixels_.data();
  for (int y = 0; y < height_; ++y) {  // GL rows are bottom-up
    const std::byte* src = texels + size_t(height_ - 1 - y) * row;
    std::transform(src, src + row, image.pixels.data() + size_t(y) * row, [](std::byte b) { return uint8_t(b); });
  }
  return image;
}

}  // namespace lfd::gpu
