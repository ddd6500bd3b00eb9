// The GPU's YUV -> RGB conversion (play/shaders/quilt_convert.frag.glsl) against the CPU
// reference media::yuv_to_rgb on a decoded frame, and an RGB picture blitted in strips (426 rows:
// a strip of 256 and one of 170): the quilt texture holds the picture exactly (rows flipped to
// GL's order and back). The context is the one LFD_GL asks for (auto: desktop OpenGL 4.5, else
// OpenGL ES 3.1, as on a Raspberry Pi; docs/arm.md).
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "media/synthetic_quilt.hpp"
#include "media/video_decoder.hpp"
#include "play/quilt_texture.hpp"
#include "render/image_metrics.hpp"
#include "tests/support/quilt_layouts.hpp"

namespace lfd::play {
namespace {

namespace fs = std::filesystem;

// Odd chroma sizes (96 x 71): the height is odd too.
render::QuiltLayout layout() { return test::quilt_layout(4, 3, 192, 142); }

int max_difference(const Image8& a, const ImageF& b) {
  int worst = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(a.pixels[i]) - int(std::lround(b.pixels[i] * 255))));
  return worst;
}

TEST(QuiltTexture, RgbPictureIsExact) {
  gpu::HeadlessContext context(gpu::gl_request_from_env());
  QuiltTexture texture;
  const Image8 picture = media::synthetic_quilt(layout(), 2);
  texture.upload(picture);
  EXPECT_EQ(max_difference(picture, gpu::image_from_texture(texture.quilt())), 0);
}

TEST(QuiltTexture, YuvFrameMatchesTheCpuConversion) {
  const fs::path video = fs::temp_directory_path() / "lfd_play_quilt_texture_test.mp4";
  media::EncoderOptions o;
  o.frame_rate = 30;
  media::write_synthetic_quilt_video(video, layout(), 3, o);
  media::VideoDecoder decoder(video, {false, 1});
  decoder.next_frame();
  const auto frame = decoder.next_frame();
  ASSERT_TRUE(frame);
  gpu::HeadlessContext context(gpu::gl_request_from_env());
  QuiltTexture texture;
  texture.upload(*frame);
  // The same coefficients and the same bilinear chroma. GL lets the linear filter work at low
  // precision (llvmpipe filters 8-bit textures in 8-bit fixed point; the CPU in doubles), which
  // moves subpixels next to chroma edges by up to a few steps: about 50 dB here. The wrong
  // matrix (BT.601 for this BT.709 stream) is far off, so the check does tell them apart.
  const Image8 cpu = media::yuv_to_rgb(*frame);
  const ImageF gpu = gpu::image_from_texture(texture.quilt());
  EXPECT_LE(max_difference(cpu, gpu), 4);
  EXPECT_GE(render::psnr(to_float(cpu), gpu), 45.0);
  media::YuvFrame wrong = *frame;
  wrong.matrix = media::YuvMatrix::kBt601;
  EXPECT_LT(render::psnr(to_float(media::yuv_to_rgb(wrong)), gpu), 40.0);
}

}  // namespace
}  // namespace lfd::play
