#include "rgbd/gl_rgbd_views.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gpu/gl/gl_flavour.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "gpu/gl/gl_quilt_target.hpp"
#include "rgbd/rgbd_frame.hpp"
#include "rgbd/rgbd_view_model.hpp"
#include "rgbd/shaders/rgbd_fill.frag.glsl.hpp"
#include "rgbd/shaders/rgbd_fullscreen.vert.glsl.hpp"
#include "rgbd/shaders/rgbd_io.h"
#include "rgbd/shaders/rgbd_resample.frag.glsl.hpp"
#include "rgbd/shaders/rgbd_warp.frag.glsl.hpp"
#include "util/error.hpp"

namespace lfd::rgbd {
namespace {

gpu::Program make_pass(const std::string& label, const std::string& fragment, std::vector<gpu::Binding> bindings) {
  return gpu::Program(label, {{GL_VERTEX_SHADER, rgbd_fullscreen_vert_glsl}, {GL_FRAGMENT_SHADER, fragment.c_str()}},
                      {}, std::move(bindings));
}

// Restores the caller's framebuffer binding and viewport when a render returns or throws.
class KeepFramebuffer {
 public:
  KeepFramebuffer() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
  }
  ~KeepFramebuffer() {
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  }
  KeepFramebuffer(const KeepFramebuffer&) = delete;
  KeepFramebuffer& operator=(const KeepFramebuffer&) = delete;

 private:
  GLint framebuffer_ = 0;
  GLint viewport_[4] = {0, 0, 0, 0};
};

void set_rect(GLint location, const PixelRect& r) {
  glUniform4i(location, r.x, r.y, r.width, r.height);
}

}  // namespace

GlRgbdViews::GlRgbdViews()
    : resample_(make_pass("rgbd resample", rgbd_resample_frag_glsl, {gpu::texture("frame", kRgbdFrameUnit)})),
      warp_(make_pass("rgbd warp", rgbd_warp_frag_glsl,
                      {gpu::texture("source", kRgbdSourceUnit), gpu::texture("shift_per_z", kRgbdShiftPerZUnit)})),
      fill_(make_pass("rgbd fill", rgbd_fill_frag_glsl, {gpu::texture("warped", kRgbdWarpedUnit)})) {
  if (gpu::current_gl_is_es()) glGenSamplers(1, &sampler_);  // ES has no glCreate*
  else glCreateSamplers(1, &sampler_);
  glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GlRgbdViews::~GlRgbdViews() {
  if (sampler_) glDeleteSamplers(1, &sampler_);
}

void GlRgbdViews::ensure_intermediates(const render::QuiltLayout& layout) {
  if (source_.width() != layout.tile_width() || source_.height() != layout.tile_height())
    source_ = gpu::Texture(GL_RGBA32F, layout.tile_width(), layout.tile_height());
  if (warped_.width() != layout.width || warped_.height() != layout.height)
    warped_ = gpu::Texture(GL_RGBA32F, layout.width, layout.height);
  if (shifts_.width() != layout.views) shifts_ = gpu::Texture(GL_R32F, layout.views, 1);
}

void GlRgbdViews::draw_into(const gpu::Program& pass, const gpu::Texture& target, int width, int height) const {
  target_.attach(0, target);
  target_.finish(1);
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glViewport(0, 0, width, height);
  pass.draw_arrays(GL_TRIANGLES, 0, 3);
}

void GlRgbdViews::render(const gpu::Texture& frame, const RgbdOptions& options,
                         const render::QuiltLayout& layout, gpu::Texture& quilt,
                         double view_cone_deg) {
  if (frame.target() != GL_TEXTURE_2D)
    throw_input_error("RGB-D frame: the texture must be a 2D texture");
  render(RgbdFrameTexture{frame.id(), frame.width(), frame.height()}, options, layout, quilt,
         view_cone_deg);
}

void GlRgbdViews::render(const RgbdFrameTexture& frame, const RgbdOptions& options,
                         const render::QuiltLayout& layout, gpu::Texture& quilt,
                         double view_cone_deg) {
  options.check("RGB-D options");
  const render::QuiltGeometry geometry = rgbd_quilt_geometry(layout, view_cone_deg);
  gpu::check_quilt_target("RGB-D views", geometry, layout, quilt);
  if (frame.id == 0) throw_input_error("RGB-D frame: no texture");
  const RgbdSplit split = split_rgbd_frame(frame.width, frame.height, options.depth_loc);
  ensure_intermediates(layout);
  const int tw = layout.tile_width(), th = layout.tile_height();

  // Each view's shift per unit z-ratio, from the one quilt geometry (rgbd_view_model.hpp).
  std::vector<float> shifts(size_t(layout.views));
  float largest = 0.0f;
  for (int j = 0; j < layout.views; ++j) {
    shifts[size_t(j)] = view_shift_px_per_z_ratio(geometry, j, tw);
    largest = std::max(largest, std::abs(shifts[size_t(j)]));
  }
  gpu::upload_texture_2d(shifts_, 0, 0, layout.views, 1, GL_RED, GL_FLOAT, shifts.data());
  const float largest_z = std::max(std::abs(relief_z_ratio(0.0f, options)),
                                   std::abs(relief_z_ratio(1.0f, options)));
  const int radius = int(std::ceil(largest * largest_z)) + 1;

  KeepFramebuffer keep;
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(triangle_.id());
  for (GLuint unit = 0; unit < kRgbdSampledUnits; ++unit) glBindSampler(unit, sampler_);

  resample_.use();
  resample_.bind_texture_id("frame", frame.id);
  set_rect(resample_.uniform("colour_rect"), split.colour);
  set_rect(resample_.uniform("depth_rect"), split.depth);
  glUniform1i(resample_.uniform("frame_height"), frame.height);
  glUniform1i(resample_.uniform("frame_top_down"), frame.top_down ? 1 : 0);
  glUniform2i(resample_.uniform("tile_size"), tw, th);
  glUniform2f(resample_.uniform("crop"), float(options.crop_pos_x), float(-options.crop_pos_y));
  glUniform1f(resample_.uniform("zoom"), float(options.zoom));
  glUniform1i(resample_.uniform("chroma_depth"), options.chroma_depth ? 1 : 0);
  glUniform1i(resample_.uniform("depth_inversion"), options.depth_inversion ? 1 : 0);
  glUniform1f(resample_.uniform("depth_cutoff"), float(options.depth_cutoff));
  draw_into(resample_, source_, tw, th);

  warp_.use();
  warp_.bind("source", source_);
  warp_.bind("shift_per_z", shifts_);
  glUniform2i(warp_.uniform("tile_size"), tw, th);
  glUniform3i(warp_.uniform("grid"), layout.cols, layout.rows, layout.views);
  glUniform1f(warp_.uniform("relief_slope"), float(options.depthiness * kReliefRatio));
  glUniform1f(warp_.uniform("focus"), float(options.focus));
  glUniform1i(warp_.uniform("radius"), radius);
  draw_into(warp_, warped_, layout.width, layout.height);

  fill_.use();
  fill_.bind("warped", warped_);
  glUniform2i(fill_.uniform("tile_size"), tw, th);
  draw_into(fill_, quilt, layout.width, layout.height);

  for (GLuint unit = 0; unit < kRgbdSampledUnits; ++unit) glBindSampler(unit, 0);
  glBindVertexArray(0);
}

ImageF render_rgbd_quilt_on_gpu(const ImageF& frame, const RgbdOptions& options,
                                const render::QuiltLayout& layout, double view_cone_deg) {
  if (frame.empty()) throw_input_error("RGB-D frame: empty image");
  const gpu::Texture frame_texture = gpu::texture_from_image(frame);
  gpu::Texture quilt(GL_RGBA32F, layout.width, layout.height);
  GlRgbdViews views;
  views.render(frame_texture, options, layout, quilt, view_cone_deg);
  return gpu::image_from_texture(quilt);
}

}  // namespace lfd::rgbd
