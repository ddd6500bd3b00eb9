#include "bridge_inproc/caller_texture.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <epoxy/glx.h>
#include <fmt/format.h>

#include "bridge_inproc/bridge_log.hpp"

namespace lfd::bridge {

namespace {

bool context_is_current() {
  // A GLFW window's context is GLX (or EGL when asked for), a headless one EGL: either counts.
  return (glXGetCurrentContext() != nullptr) || (eglGetCurrentContext() != EGL_NO_CONTEXT);
}

GLint get_int(GLenum what) {
  GLint v = 0;
  glGetIntegerv(what, &v);
  return v;
}

void drain_errors() {
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
}

// The pack state glGetTexImage / glReadPixels follow, set to tight rows and put back after.
class PackState {
 public:
  PackState()
      : alignment_(get_int(GL_PACK_ALIGNMENT)),
        row_length_(get_int(GL_PACK_ROW_LENGTH)),
        skip_rows_(get_int(GL_PACK_SKIP_ROWS)),
        skip_pixels_(get_int(GL_PACK_SKIP_PIXELS)),
        pack_buffer_(get_int(GL_PIXEL_PACK_BUFFER_BINDING)) {
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    if (pack_buffer_) glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  }
  ~PackState() {
    glPixelStorei(GL_PACK_ALIGNMENT, alignment_);
    glPixelStorei(GL_PACK_ROW_LENGTH, row_length_);
    glPixelStorei(GL_PACK_SKIP_ROWS, skip_rows_);
    glPixelStorei(GL_PACK_SKIP_PIXELS, skip_pixels_);
    if (pack_buffer_) glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(pack_buffer_));
  }

 private:
  GLint alignment_, row_length_, skip_rows_, skip_pixels_, pack_buffer_;
};

// Binds `name` to GL_TEXTURE_2D of the active unit and puts the previous binding back after.
class TextureBinding {
 public:
  explicit TextureBinding(GLuint name) : previous_(get_int(GL_TEXTURE_BINDING_2D)) {
    glBindTexture(GL_TEXTURE_2D, name);
  }
  ~TextureBinding() { glBindTexture(GL_TEXTURE_2D, GLuint(previous_)); }

 private:
  GLint previous_;
};

void require_context(const char* what) {
  if (!context_is_current()) refuse(fmt::format("no GL context is current on the calling thread ({})", what));
}

}  // namespace

void check_readable_format(unsigned format) {
  switch (format) {
    case 0x1907: case 0x1908: case 0x80E1: case 0x1903: case 0x8C41: case 0x8C43: case 0x822E: case 0x8814:
    case 0x8059:
      return;
    default:
      refuse(fmt::format("pixel format 0x{:X} is not supported (RGB, RGBA, BGRA, Red, SRGB, SRGB_A, R32F, "
                         "RGBA32F, RGB10_A2)", format));
  }
}

RgbaPixels read_caller_texture(unsigned name, int width, int height, std::vector<uint8_t> storage) {
  if (name == 0) refuse("texture 0");
  if (width <= 0 || height <= 0) refuse(fmt::format("texture size {}x{}", width, height));
  require_context("the texture belongs to the caller's context");
  if (!glIsTexture(name)) refuse(fmt::format("texture {} is not a texture of the current context", name));
  drain_errors();
  RgbaPixels out;
  out.width = width;
  out.height = height;
  out.bytes = std::move(storage);
  out.bytes.resize(size_t(width) * height * 4);
  if (epoxy_is_desktop_gl()) {
    TextureBinding bind(name);
    if (glGetError() != GL_NO_ERROR) refuse(fmt::format("texture {} is not a 2D texture", name));
    GLint w = 0, h = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    if (w != width || h != height)
      refuse(fmt::format("texture {} is {}x{}, not the {}x{} given", name, w, h, width, height));
    PackState pack;
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.bytes.data());
  } else {
    GLint w = 0, h = 0;
    {
      TextureBinding bind(name);
      if (glGetError() != GL_NO_ERROR) refuse(fmt::format("texture {} is not a 2D texture", name));
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
    }
    if (w != width || h != height)
      refuse(fmt::format("texture {} is {}x{}, not the {}x{} given", name, w, h, width, height));
    const GLint previous = get_int(GL_READ_FRAMEBUFFER_BINDING);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, name, 0);
    const bool complete = glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (complete) {
      PackState pack;
      glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, out.bytes.data());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
    glDeleteFramebuffers(1, &fbo);
    if (!complete) refuse(fmt::format("texture {} cannot be read (not colour-renderable)", name));
  }
  if (glGetError() != GL_NO_ERROR) refuse(fmt::format("texture {} could not be read", name));
  return out;
}

unsigned upload_to_caller_texture(unsigned name, const RgbaPixels& pixels) {
  require_context("the texture is made in the caller's context");
  GLuint texture = name;
  if (texture == 0 || !glIsTexture(texture)) glGenTextures(1, &texture);
  const GLint unpack_alignment = get_int(GL_UNPACK_ALIGNMENT);
  const GLint unpack_row_length = get_int(GL_UNPACK_ROW_LENGTH);
  const GLint unpack_buffer = get_int(GL_PIXEL_UNPACK_BUFFER_BINDING);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  if (unpack_buffer) glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  {
    TextureBinding bind(texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, pixels.width, pixels.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 pixels.bytes.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, unpack_alignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, unpack_row_length);
  if (unpack_buffer) glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(unpack_buffer));
  return texture;
}

}  // namespace lfd::bridge
