#include "play/quilt_texture.hpp"

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

void QuiltTexture::upload(const Image8& rgb) {
  // RGB8: the format OpenGL ES takes GL_RGB bytes into (an RGBA8 texture wants GL_RGBA there).
  upload_plane(planes_[0], GL_RGB8, GL_RGB, rgb.width, rgb.height, rgb.pixels.data(), rgb.width);
  ensure_quilt(rgb.width, rgb.height);
  convert(false, {});
  // A still is converted once: its RGB plane would only double what the quilt holds (on
  // llvmpipe and on boards sharing memory with the GPU, as much again as the RGBA quilt;
  // docs/serve.md, "Memory"). A video keeps its planes for the next frame.
  planes_[0] = gpu::Texture();
}

void QuiltTexture::upload(const media::YuvFrame& frame) {
  for (int p = 0; p < 3; ++p) {
    const media::YuvPlane& plane = frame.planes[p];
    upload_plane(planes_[p], GL_R8, GL_RED, plane.width, plane.height, plane.data, plane.stride);
  }
  ensure_quilt(frame.width, frame.height);
  convert(true, media::yuv_to_rgb_coefficients(frame.matrix, frame.range));
}

void QuiltTexture::convert(bool yuv, const media::YuvToRgb& t) {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glViewport(0, 0, quilt_.width(), quilt_.height());
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  program_.use();
  glUniform1i(program_.uniform("u_is_yuv"), yuv ? 1 : 0);
  if (yuv) {
    glUniformMatrix3fv(program_.uniform("u_yuv_matrix"), 1, GL_FALSE, t.matrix.data());
    glUniform3fv(program_.uniform("u_yuv_offset"), 1, t.offset.data());
  }
  // An RGB picture is plane 0 alone; the shader reads U and V only for YUV, so the picture
  // stands at their points too (every declared point holds a texture of ours).
  program_.bind("plane0", planes_[0]);
  program_.bind("plane1", planes_[yuv ? 1 : 0]);
  program_.bind("plane2", planes_[yuv ? 2 : 0]);
  glBindVertexArray(triangle_.id());
  program_.draw_arrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gpu::check_gl("converting the quilt");
}

}  // namespace lfd::play
