#include "gpu/panel/gl_direct_panel.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "gpu/panel/gl_interlacer.hpp"
#include "gpu/panel/shaders/direct_panel.comp.glsl.hpp"
#include "gpu/panel/shaders/direct_panel.frag.glsl.hpp"
#include "gpu/panel/shaders/interlace.vert.glsl.hpp"
#include "gpu/panel/shaders/lens_view_io.h"
#include "gpu/planes/shaders/plane_table_io.h"
#include "interlace/interlacer.hpp"
#include "util/error.hpp"

namespace lfd::gpu {

// direct_panel.comp.glsl: each invocation of a group computes at most one plane's factors.
static_assert(kDirectPanelPlaneBatch <= kDirectPanelTileWidth * kDirectPanelTileHeight,
              "a batch of plane factors is one plane per invocation of a tile");

GlDirectPanel::GlDirectPanel(const display::LensModel& lens, bool hardware_bilinear, DirectPanelPass pass)
    : calibration_(lens.calibration()),
      panel_width_(lens.calibration().screen_w),
      panel_height_(lens.calibration().screen_h),
      hardware_bilinear_(hardware_bilinear),
      pass_(pass),
      lens_view_(lens) {
  if (hardware_bilinear_) set_plane_bilinear(linear_);
}

const Program& GlDirectPanel::program(render::PlaneFilter filter, GLenum panel_format) {
  const auto key = std::make_pair(int(filter), panel_format);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    const bool bilinear = filter == render::PlaneFilter::kBilinear;
    std::vector<std::string> defines = {std::string("BILINEAR ") + (bilinear ? "1" : "0"),
                                        std::string("HW_BILINEAR ") + (hardware_bilinear_ ? "1" : "0")};
    const std::string name = std::string("direct panel (") + (bilinear ? "bilinear" : "nearest") +
                             (panel_format ? ", compute)" : ")");
    if (panel_format) {
      defines.push_back(std::string("PANEL_FORMAT ") + image_format_qualifier(panel_format, "panel texture"));
      defines.push_back(std::string("PLANE_MAJOR ") + (pass_ == DirectPanelPass::kComputePlaneMajor ? "1" : "0"));
    }
    std::vector<Binding> bindings{texture("planes", kDirectPanelPlanesUnit),
                                  storage_buffer("plane_table", kPlaneTableBinding, Access::read)};
    if (panel_format) bindings.push_back(image("panel", kDirectPanelImage, Access::write));
    bindings = GlLensView::bindings_after(std::move(bindings));
    Program p = panel_format
                    ? Program(name, {{GL_COMPUTE_SHADER, direct_panel_comp_glsl}}, defines, std::move(bindings))
                    : Program(name, {{GL_VERTEX_SHADER, interlace_vert_glsl}, {GL_FRAGMENT_SHADER, direct_panel_frag_glsl}},
                              defines, std::move(bindings));
    lens_view_.set_uniforms(p);
    it = programs_.emplace(key, std::move(p)).first;
  }
  return it->second;
}

const Program& GlDirectPanel::prepare(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                                      const render::ReferenceCamera& ref,
                                      const interlace::DirectPanelOptions& options, GLenum panel_format) {
  const Program& p = program(options.filter, panel_format);
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
  p.use();
  lens_view_.bind(p);
  p.bind("planes", planes.texels);
  const bool sampled = hardware_bilinear_ && options.filter == render::PlaneFilter::kBilinear;
  glBindSampler(kDirectPanelPlanesUnit, sampled ? linear_.id() : 0);
  p.bind("plane_table", planes.table.buffer);
  return p;
}

void GlDirectPanel::draw(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                         const render::ReferenceCamera& ref, const interlace::DirectPanelOptions& options) {
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, panel_width_, panel_height_);
  const Program& p = prepare(planes, geometry, ref, options, 0);
  glBindVertexArray(triangle_.id());
  p.draw_arrays(GL_TRIANGLES, 0, 3);
  glBindSampler(kDirectPanelPlanesUnit, 0);
  check_gl("the direct panel pass");
}

void GlDirectPanel::run(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                        const render::ReferenceCamera& ref, const interlace::DirectPanelOptions& options,
                        Texture& panel) {
  if (panel.width() != panel_width_ || panel.height() != panel_height_ || panel.layers())
    throw_input_error("panel: texture is {}x{} but the display is {}x{}", panel.width(), panel.height(),
                      panel_width_, panel_height_);
  if (pass_ == DirectPanelPass::kFragment) {
    target_.attach(0, panel);
    target_.finish(1);
    glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
    draw(planes, geometry, ref, options);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return;
  }
  const Program& p = prepare(planes, geometry, ref, options, panel.internal_format());
  p.bind("panel", panel);
  p.dispatch((GLuint(panel_width_) + kDirectPanelTileWidth - 1) / kDirectPanelTileWidth,
             (GLuint(panel_height_) + kDirectPanelTileHeight - 1) / kDirectPanelTileHeight);
  glBindSampler(kDirectPanelPlanesUnit, 0);
  // The panel is read next by texture fetches (a window's blit), image loads or a read-back.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("the direct panel pass (compute)");
}

ImageF direct_panel_on_gpu(const render::SweepingPlanes& planes, const render::QuiltGeometry& geometry,
                           const render::ReferenceCamera& ref, const display::LensModel& lens,
                           const interlace::DirectPanelOptions& options, bool hardware_bilinear,
                           DirectPanelPass stage) {
  const GlPlanes gl_planes = upload_planes(planes);
  GlDirectPanel pass(lens, hardware_bilinear, stage);
  Texture panel(GL_RGBA32F, lens.calibration().screen_w, lens.calibration().screen_h);
  pass.run(gl_planes, geometry, ref, options, panel);
  return image_from_texture(panel);
}

}  // namespace lfd::gpu
