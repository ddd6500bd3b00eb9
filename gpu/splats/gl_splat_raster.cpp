#include "gpu/splats/gl_splat_raster.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/splat_composite.frag.glsl.hpp"
#include "gpu/splats/shaders/splat_composite.vert.glsl.hpp"
#include "gpu/splats/shaders/splat_raster.frag.glsl.hpp"
#include "gpu/splats/shaders/splat_raster.vert.glsl.hpp"

namespace lfd::gpu {
namespace {

Program splat_program(bool layered) {
  std::vector<Binding> bindings{storage_buffer("records", kSplatRecordsBinding, Access::read),
                                storage_buffer("sorted_ids", kSplatValuesBinding, Access::read)};
  if (layered) bindings.push_back(storage_buffer("layers", kSplatLayersBinding, Access::read));
  return Program(layered ? "splat raster (layered)" : "splat raster",
                 {{GL_VERTEX_SHADER, splat_raster_vert_glsl}, {GL_FRAGMENT_SHADER, splat_raster_frag_glsl}},
                 layered ? std::vector<std::string>{"LAYERED 1"} : std::vector<std::string>{}, std::move(bindings));
}

glm::ivec4 region(const SplatRasterTarget& t) {
  return t.scissor.z > 0 ? t.scissor : glm::ivec4(t.viewport_origin, t.image_size);
}

}  // namespace

GlSplatRaster::GlSplatRaster()
    : splats_(splat_program(false)),
      composite_blend_("splat composite (in place)",
                       {{GL_VERTEX_SHADER, splat_composite_vert_glsl}, {GL_FRAGMENT_SHADER, splat_composite_frag_glsl}}),
      composite_copy_("splat composite (from a texture)",
                      {{GL_VERTEX_SHADER, splat_composite_vert_glsl}, {GL_FRAGMENT_SHADER, splat_composite_frag_glsl}},
                      {"FROM_TEXTURE 1"}, {texture("accumulation", kSplatAccumulationUnit)}) {
  if (epoxy_has_gl_extension("GL_ARB_shader_viewport_layer_array")) splats_layered_ = splat_program(true);
}

void begin_raster_target(const SplatRasterTarget& target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glViewport(target.viewport_origin.x, target.viewport_origin.y, target.image_size.x, target.image_size.y);
  const glm::ivec4 r = region(target);
  glEnable(GL_SCISSOR_TEST);
  glScissor(r.x, r.y, r.z, r.w);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void end_raster_target() {
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void enable_front_to_back_blend() {
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
}

void GlSplatRaster::begin(const SplatRasterTarget& target) const {
  begin_raster_target(target);
  glBindVertexArray(vertex_array_.id());
}

void GlSplatRaster::end() const { end_raster_target(); }

void GlSplatRaster::clear(const SplatRasterTarget& target) const {
  begin(target);
  const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // C = 0, T = 1
  glClearBufferfv(GL_COLOR, 0, empty);
  end();
  check_gl("clearing a splat target");
}

void GlSplatRaster::draw(const Buffer& records, const Buffer& sorted_ids, const Buffer& indirect,
                         const SplatRasterTarget& target, const Buffer* layers) const {
  const Program& program = layers ? splats_layered_ : splats_;
  if (!program.id())
    throw std::runtime_error("layered splat raster needs GL_ARB_shader_viewport_layer_array");
  begin(target);
  program.bind("records", records);
  program.bind("sorted_ids", sorted_ids);
  if (layers) program.bind("layers", *layers);
  glProgramUniform2i(program.id(), program.uniform("image_size"), target.image_size.x, target.image_size.y);
  glProgramUniform2f(program.id(), program.uniform("viewport_origin"), float(target.viewport_origin.x),
                     float(target.viewport_origin.y));
  program.use();
  enable_front_to_back_blend();
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, indirect.id());
  program.draw_arrays_indirect(GL_TRIANGLE_STRIP, 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  end();
  check_gl("drawing splats");
}

void GlSplatRaster::draw(const SplatBuffers& buffers, const SplatRasterTarget& target, const Buffer* layers) const {
  draw(buffers.records, buffers.values, buffers.draw, target, layers);
}

void GlSplatRaster::composite_background(const SplatRasterTarget& target, const glm::vec3& background,
                                         TargetAlpha alpha) const {
  const bool keep_transmittance = alpha == TargetAlpha::kTransmittance;
  begin(target);
  const GLuint p = composite_blend_.id();
  glProgramUniform3fv(p, composite_blend_.uniform("background"), 1, glm::value_ptr(background));
  glProgramUniform1f(p, composite_blend_.uniform("alpha_out"), keep_transmittance ? 0.0f : 1.0f);
  composite_blend_.use();
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  // rgb: bg * T + C; alpha: T kept (0 * 0 + T) or 1 * 1 + 0.
  glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, keep_transmittance ? GL_ZERO : GL_ONE,
                      keep_transmittance ? GL_ONE : GL_ZERO);
  composite_blend_.draw_arrays(GL_TRIANGLES, 0, 3);
  end();
  check_gl("compositing the background");
}

void GlSplatRaster::composite_from(const Texture& accumulation, const SplatRasterTarget& target,
                                   const glm::vec3& background) const {
  begin(target);
  const GLuint p = composite_copy_.id();
  glProgramUniform3fv(p, composite_copy_.uniform("background"), 1, glm::value_ptr(background));
  glProgramUniform2i(p, composite_copy_.uniform("viewport_origin"), target.viewport_origin.x,
                     target.viewport_origin.y);
  composite_copy_.bind("accumulation", accumulation);
  composite_copy_.use();
  glDisable(GL_BLEND);
  composite_copy_.draw_arrays(GL_TRIANGLES, 0, 3);
  glBindTextureUnit(kSplatAccumulationUnit, 0);
  end();
  check_gl("compositing into the target");
}

}  // namespace lfd::gpu
