#include "play/quilt_texture.hpp"

#include <algorithm>

#include "play/shaders/quilt_convert.frag.glsl.hpp"
#include "play/shaders/quilt_convert.vert.glsl.hpp"
#include "play/shaders/quilt_convert_io.h"

namespace lfd::play {
namespace {

// (Re)allocates `texture` when its size or format differs.
void ensure_texture(gpu::Texture& texture, GLenum format, int width, int height) {
  if (texture.width() == width && texture.height() == height && texture.internal_format() == format) return;
  texture = gpu::Texture(format, width, height);
  texture.set_filter(GL_LINEAR);
}

void upload_plane(gpu::Texture& texture, GLenum format, GLenum data_format, int width, int height,
                  const uint8_t* data, int row_length_texels) {
  ensure_texture(texture, format, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length_texels);
  gpu::upload_texture_2d(texture, 0, 0, width, height, data_format, GL_UNSIGNED_BYTE, data);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

}  // namespace

QuiltTexture::QuiltTexture()
    : program_("quilt convert", {{GL_VERTEX_SHADER, quilt_convert_vert_glsl}, {GL_FRAGMENT_SHADER, quilt_convert_frag_glsl}},
               {},
               {gpu::texture("plane0", kQuiltPlane0Unit), gpu::texture("plane1", kQuiltPlane1Unit),
                gpu::texture("plane2", kQuiltPlane2Unit)}) {}

void QuiltTexture::ensure_quilt(int width, int height) {
  if (quilt_.width() == width && quilt_.height() == height) return;
  quilt_ = gpu::Texture(GL_RGBA8, width, height);
  quilt_.set_filter(GL_LINEAR);
  target_.attach(0, quilt_);
  target_.finish(1);
}

// A still goes up in strips of this many rows: the whole picture as one RGB texture would hold,
// while it is converted, as much again as the quilt (an RGB8 texture takes 4 bytes a texel on
// llvmpipe; on a board sharing its memory with the GPU, 256 MiB for an 8K quilt; docs/serve.md,
// "Memory").
constexpr int kStillStripRows = 256;

void QuiltTexture::upload(const Image8& rgb) {
  ensure_quilt(rgb.width, rgb.height);
  const int strip_rows = std::min(rgb.height, kStillStripRows);
  const gpu::Texture strip(GL_RGB8, rgb.width, strip_rows);
  const gpu::Framebuffer source;
  source.attach(0, strip);
  source.finish(1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_.id());
  glDisable(GL_SCISSOR_TEST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  for (int top = 0; top < rgb.height; top += strip_rows) {
    const int rows = std::min(strip_rows, rgb.height - top);
    gpu::upload_texture_2d(strip, 0, 0, rgb.width, rows, GL_RGB, GL_UNSIGNED_BYTE,
                           rgb.pixels.data() + std::size_t(top) * std::size_t(rgb.width) * 3);
    // Picture row top + j (rows top-down) is quilt row height - 1 - top - j (GL's rows, view
    // 0's tile at the bottom): the blit flips as it turns RGB8 into RGBA8, texel for texel.
    glBlitFramebuffer(0, 0, rgb.width, rows, 0, rgb.height - top, rgb.width, rgb.height - top - rows,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gpu::check_gl("uploading the quilt");
}

void QuiltTexture::upload(const media::YuvFrame& frame) {
  for (int p = 0; p < 3; ++p) {
    const media::YuvPlane& plane = frame.planes[p];
    upload_plane(planes_[p], GL_R8, GL_RED, plane.width, plane.height, plane.data, plane.stride);
  }
  ensure_quilt(frame.width, frame.height);
  convert(media::yuv_to_rgb_coefficients(frame.matrix, frame.range));
}

void QuiltTexture::convert(const media::YuvToRgb& t) {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glViewport(0, 0, quilt_.width(), quilt_.height());
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  program_.use();
  glUniformMatrix3fv(program_.uniform("u_yuv_matrix"), 1, GL_FALSE, t.matrix.data());
  glUniform3fv(program_.uniform("u_yuv_offset"), 1, t.offset.data());
  program_.bind("plane0", planes_[0]);
  program_.bind("plane1", planes_[1]);
  program_.bind("plane2", planes_[2]);
  glBindVertexArray(triangle_.id());
  program_.draw_arrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gpu::check_gl("converting the quilt");
}

}  // namespace lfd::play
