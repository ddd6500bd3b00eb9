#include "gpu/panel/gl_interlacer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/gl/gl_limits.hpp"
#include "gpu/panel/shaders/interlace.comp.glsl.hpp"
#include "gpu/panel/shaders/interlace.frag.glsl.hpp"
#include "gpu/panel/shaders/interlace.vert.glsl.hpp"
#include "gpu/panel/shaders/lens_view_io.h"
#include "util/error.hpp"

namespace lfd::gpu {

GlInterlacer::GlInterlacer(const display::LensModel& lens, const render::QuiltLayout& layout,
                           interlace::InterlaceOptions options, InterlacePass pass)
    : layout_(layout),
      options_(options),
      pass_(pass),
      calibration_(lens.calibration()),
      panel_width_(lens.calibration().screen_w),
      panel_height_(lens.calibration().screen_h),
      program_("interlace", {{GL_VERTEX_SHADER, interlace_vert_glsl}, {GL_FRAGMENT_SHADER, interlace_frag_glsl}}, {},
               GlLensView::bindings_after({texture("quilt", kInterlaceQuiltUnit)})),
      lens_view_(lens) {
  layout_.check("quilt");
  set_uniforms(program_);
}

void GlInterlacer::set_uniforms(const Program& program) const {
  const GLuint p = program.id();
  const auto at = [&](const char* name) { return program.uniform(name); };
  lens_view_.set_uniforms(program);
  glProgramUniform1i(p, at("views"), layout_.views);
  glProgramUniform1i(p, at("quilt_cols"), layout_.cols);
  glProgramUniform2i(p, at("tile_size"), layout_.tile_width(), layout_.tile_height());
  // Interlacer::sample_for's aspect fit as a scale of (u - 0.5, v - 0.5) (docs/display-model.md
  // "Vendor interlacing rules").
  const interlace::AspectFit fit = interlace::aspect_fit(calibration_, layout_.aspect, options_.overscan, layout_.tile_height());
  glProgramUniform2f(p, at("aspect_scale"), float(fit.scale_u), float(fit.scale_v));
  glProgramUniform1i(p, at("invert_views"), options_.invert_views ? 1 : 0);
  glProgramUniform1i(p, at("linear_blend"), options_.blend == interlace::ViewBlend::kLinear);
  glProgramUniform1f(p, at("fringe"), float(calibration_.fringe));
  check_gl("setting up the interlacing shader");
}

const Program& GlInterlacer::compute_program(GLenum panel_format) {
  auto it = compute_programs_.find(panel_format);
  if (it == compute_programs_.end()) {
    Program p("interlace (compute)", {{GL_COMPUTE_SHADER, interlace_comp_glsl}},
              {std::string("PANEL_FORMAT ") + image_format_qualifier(panel_format, "panel texture")},
              GlLensView::bindings_after(
                  {texture("quilt", kInterlaceQuiltUnit), image("panel", kInterlacePanelImage, Access::write)}));
    set_uniforms(p);
    it = compute_programs_.emplace(panel_format, std::move(p)).first;
  }
  return it->second;
}

void GlInterlacer::check_quilt(const Texture& quilt) const {
  if (quilt.width() != layout_.width || quilt.height() != layout_.height || quilt.layers())
    throw_input_error("quilt: texture is {}x{}{} but the layout says {}x{}", quilt.width(),
                      quilt.height(), quilt.layers() ? " (an array)" : "", layout_.width,
                      layout_.height);
}

void GlInterlacer::draw(const Texture& quilt) const {
  check_quilt(quilt);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, panel_width_, panel_height_);
  program_.use();
  program_.bind("quilt", quilt);
  lens_view_.bind(program_);
  glBindVertexArray(triangle_.id());
  program_.draw_arrays(GL_TRIANGLES, 0, 3);
  check_gl("interlacing");
}

void GlInterlacer::interlace(const Texture& quilt, Texture& panel) {
  if (panel.width() != panel_width_ || panel.height() != panel_height_ || panel.layers())
    throw_input_error("panel: texture is {}x{} but the display is {}x{}", panel.width(),
                      panel.height(), panel_width_, panel_height_);
  if (pass_ == InterlacePass::kFragment) {
    target_.attach(0, panel);
    target_.finish(1);
    glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
    draw(quilt);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return;
  }
  check_quilt(quilt);
  const Program& p = compute_program(panel.internal_format());
  p.use();
  p.bind("quilt", quilt);
  lens_view_.bind(p);
  p.bind("panel", panel);
  p.dispatch((GLuint(panel_width_) + kInterlaceGroupWidth - 1) / kInterlaceGroupWidth,
                    (GLuint(panel_height_) + kInterlaceGroupHeight - 1) / kInterlaceGroupHeight, 1);
  // The panel is read next by texture fetches (a window's blit), image loads or a read-back.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("interlacing (compute)");
}

Texture texture_from_image(const ImageF& image) {
  if (image.channels != 1 && image.channels != 3 && image.channels != 4)
    throw std::invalid_argument("texture_from_image: 1, 3 or 4 channels");
  std::vector<float> rgba(size_t(image.width) * image.height * 4);
  for (int y = 0; y < image.height; ++y) {
    const float* src = image.row(image.height - 1 - y);  // GL rows run bottom-up
    float* dst = rgba.data() + size_t(y) * image.width * 4;
    for (int x = 0; x < image.width; ++x, src += image.channels, dst += 4) {
      const bool grey = image.channels == 1;
      dst[0] = src[0];
      dst[1] = src[grey ? 0 : 1];
      dst[2] = src[grey ? 0 : 2];
      dst[3] = image.channels == 4 ? src[3] : 1.f;
    }
  }
  Texture texture(GL_RGBA32F, image.width, image.height);
  upload_texture_2d(texture, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT,
                      rgba.data());
  check_gl("uploading an image");
  return texture;
}

ImageF image_from_texture(const Texture& texture) {
  const std::vector<float> rgba = read_texture_rgba(texture);
  ImageF image(texture.width(), texture.height(), 3);
  for (int y = 0; y < image.height; ++y) {
    const float* src = rgba.data() + size_t(image.height - 1 - y) * image.width * 4;
    float* dst = image.row(y);
    for (int x = 0; x < image.width; ++x, src += 4, dst += 3) std::copy(src, src + 3, dst);
  }
  return image;
}

ImageF interlace_on_gpu(const ImageF& quilt, const render::QuiltLayout& layout,
                        const display::LensModel& lens, const interlace::InterlaceOptions& options,
                        InterlacePass pass) {
  if (quilt.width != layout.width || quilt.height != layout.height)
    throw_input_error("quilt: image is {}x{} but the layout says {}x{}", quilt.width,
                      quilt.height, layout.width, layout.height);
  const int max_size = gl_limits().texture_size;
  const auto& cal = lens.calibration();
  if (std::max(quilt.width, quilt.height) > max_size ||
      std::max(cal.screen_w, cal.screen_h) > max_size)
    throw_input_error("quilt {}x{} or panel {}x{}: larger than this GL's textures ({} pixels)",
                      quilt.width, quilt.height, cal.screen_w, cal.screen_h, max_size);
  GlInterlacer interlacer(lens, layout, options, pass);
  const Texture quilt_texture = texture_from_image(quilt);
  Texture panel(GL_RGBA32F, cal.screen_w, cal.screen_h);
  interlacer.interlace(quilt_texture, panel);
  return image_from_texture(panel);
}

}  // namespace lfd::gpu
