#pragma once
// The quilt on the GPU (docs/play.md "How a frame is shown"): an RGBA8 quilt texture with GL's
// rows (view 0's tile at the bottom-left), the texture gpu::GlInterlacer reads, from a decoded
// picture: an RGB image goes up in strips blitted into it (flipped, RGB8 to RGBA8); a video
// frame's YUV 4:2:0 planes are uploaded as-is (three R8 textures: the CPU does no colour
// conversion) and drawn by one shader (play/shaders/quilt_convert.frag.glsl). Needs a current GL 4.5 context (the player's window).
#include "gpu/gl/gl_objects.hpp"
#include "media/yuv_frame.hpp"
#include "util/image.hpp"

namespace lfd::play {

class QuiltTexture {
 public:
  QuiltTexture();
  // An RGB image (rows top-down).
  void upload(const Image8& rgb);
  // A video frame's planes (strides honoured: no repacking on the CPU).
  void upload(const media::YuvFrame& frame);
  // The quilt as the interlacer reads it (empty before the first upload).
  const gpu::Texture& quilt() const { return quilt_; }
  bool empty() const { return quilt_.width() == 0; }

 private:
  void ensure_quilt(int width, int height);
  void convert(const media::YuvToRgb& coefficients);

  gpu::Program program_;
  gpu::VertexArray triangle_;
  gpu::Framebuffer target_;
  gpu::Texture quilt_;
  gpu::Texture planes_[3];  // a video frame's Y, U, V (R8)
};

}  // namespace lfd::play
