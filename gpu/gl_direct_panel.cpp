#include "gpu/gl_direct_panel.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "gpu/gl_interlacer.hpp"
#include "gpu/shaders/direct_panel.frag.glsl.hpp"
#include "gpu/shaders/interlace.vert.glsl.hpp"
#include "gpu/shaders/lens_view_io.h"
#include "gpu/shaders/plane_table_io.h"
#include "interlace/interlacer.hpp"
#include "util/error.hpp"

namespace lfd::gpu {

GlDirectPanel::GlDirectPanel(const display::LensModel& lens, bool hardware_bilinear)
    : calibration_(lens.calibration()),
      panel_width_(lens.calibration().screen_w),
      panel_height_(lens.calibration().screen_h),
      hardware_bilinear_(hardware_bilinear),
      lens_view_(lens) {
  if (hardware_bilinear_) set_plane_bilinear(linear_);
}

const Program& GlDirectPanel::program(render::PlaneFilter filter) {
  auto it = programs_.find(int(filter));
  if (it == programs_.end()) {
    const bool bilinear = filter == render::PlaneFilter::kBilinear;
    Program p(std::string("direct panel (") + (bilinear ? "bilinear" : "nearest") + ")",
              {{GL_VERTEX_SHADER, interlace_vert_glsl}, {GL_FRAGMENT_SHADER, direct_panel_frag_glsl}},
              {std::string("BILINEAR ") + (bilinear ? "1" : "0"),
               std::string("HW_BILINEAR ") + (hardware_bilinear_ ? "1" : "0")});
    lens_view_.set_uniforms(p);
    it = programs_.emplace(int(filter), std::move(p)).first;
  }
  return it->second;
}

void GlDirectPanel::draw(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                         const render::ReferenceCamera& ref, const interlace::DirectPanelOptions& options) {
  const Program& p = program(options.filter);
  const GLuint id = p.id();
  const auto at = [&](const char* name) { return p.uniform(name); };
  glProgramUniform2i(id, at("plane_size"), planes.width, planes.height);
  glProgramUniform1f(id, at("focal_distance"), geometry.focal_distance);
  glProgramUniform1f(id, at("tan_x"), geometry.base.tan_half_fov_x());
  glProgramUniform1f(id, at("tan_y"), geometry.base.tan_half_fov_y());
  glProgramUniform1f(id, at("tan_rx"), ref.camera.tan_half_fov_x());
  glProgramUniform1f(id, at("tan_ry"), ref.camera.tan_half_fov_y());
  glProgramUniform1f(id, at("d_forward_eff"), ref.d_forward_eff);
  // QuiltGeometry::view_offset_at's factors, as the CPU computes them (std::tan in float).
  glProgramUniform1f(id, at("two_focal_distance"), 2.0f * geometry.focal_distance);
  glProgramUniform1f(id, at("tan_half_cone"), std::tan(0.5f * geometry.view_cone_rad));
  const interlace::AspectFit fit = interlace::aspect_fit(
      calibration_, double(geometry.base.width) / double(geometry.base.height), options.overscan,
      geometry.base.height);
  glProgramUniform2f(id, at("aspect_scale"), float(fit.scale_u), float(fit.scale_v));
  glProgramUniform1i(id, at("invert_views"), options.invert_views ? 1 : 0);
  glProgramUniform1f(id, at("fringe"), float(calibration_.fringe));
  glProgramUniform3f(id, at("background"), options.background.x, options.background.y, options.background.z);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, panel_width_, panel_height_);
  p.use();
  lens_view_.bind();
  glBindTextureUnit(kDirectPanelPlanesUnit, planes.texels.id());
  const bool sampled = hardware_bilinear_ && options.filter == render::PlaneFilter::kBilinear;
  glBindSampler(kDirectPanelPlanesUnit, sampled ? linear_.id() : 0);
  planes.table.buffer.bind_storage(kPlaneTableBinding);
  glBindVertexArray(triangle_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(kDirectPanelPlanesUnit, 0);
  check_gl("the direct panel pass");
}

void GlDirectPanel::run(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                        const render::ReferenceCamera& ref, const interlace::DirectPanelOptions& options,
                        Texture& panel) {
  if (panel.width() != panel_width_ || panel.height() != panel_height_ || panel.layers())
    throw_input_error("panel: texture is {}x{} but the display is {}x{}", panel.width(), panel.height(),
                      panel_width_, panel_height_);
  target_.attach(0, panel);
  target_.finish(1);
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  draw(planes, geometry, ref, options);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

ImageF direct_panel_on_gpu(const render::SweepingPlanes& planes, const render::QuiltGeometry& geometry,
                           const render::ReferenceCamera& ref, const display::LensModel& lens,
                           const interlace::DirectPanelOptions& options, bool hardware_bilinear) {
  const GlPlanes gl_planes = upload_planes(planes);
  GlDirectPanel pass(lens, hardware_bilinear);
  Texture panel(GL_RGBA32F, lens.calibration().screen_w, lens.calibration().screen_h);
  pass.run(gl_planes, geometry, ref, options, panel);
  return image_from_texture(panel);
}

}  // namespace lfd::gpu
