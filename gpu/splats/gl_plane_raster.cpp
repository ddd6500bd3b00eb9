#include "gpu/splats/gl_plane_raster.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "gpu/splats/gl_depth_binning.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/g2lf_plane_batches.comp.glsl.hpp"
#include "gpu/splats/shaders/g2lf_plane_convert.comp.glsl.hpp"
#include "gpu/splats/shaders/g2lf_plane_copy.comp.glsl.hpp"
#include "gpu/planes/shaders/plane_io.h"

namespace lfd::gpu {
namespace {

constexpr size_t kAccumulationTexel = 16;  // RGBA32F

}  // namespace

Program plane_convert_program(const char* format, bool quantize_u8) {
  return Program(std::string("planes: convert to ") + format,
                 {{GL_COMPUTE_SHADER, g2lf_plane_convert_comp_glsl}},
                 {std::string("PLANE_FORMAT ") + format, std::string("QUANTIZE_U8 ") + (quantize_u8 ? "1" : "0")},
                 {storage_buffer("plane_table", kPlaneTableBinding, Access::read),
                  image("accumulation", kPlaneAccumulationImage, Access::read_write),
                  image("planes", kPlaneTexelsImage, Access::write)});
}

const char* plane_raster_name(PlaneRaster raster) {
  return raster == PlaneRaster::kLayered ? "layered" : "batched";
}

int plane_batch_layers(PlaneFormat format, int max_planes, int width, int height, size_t budget_bytes) {
  if (format == PlaneFormat::kRgba32f) return 0;
  const size_t layer = size_t(width) * size_t(height) * kAccumulationTexel;
  return int(std::clamp<size_t>(budget_bytes / std::max<size_t>(layer, 1), 1, size_t(std::max(max_planes, 1))));
}

size_t plane_raster_bytes(PlaneFormat format, int batch_layers, int width, int height, size_t gaussians) {
  if (format == PlaneFormat::kRgba32f) return 0;
  return size_t(batch_layers) * size_t(width) * size_t(height) * kAccumulationTexel +
         gaussians * 2 * sizeof(uint32_t);
}

GlPlaneRaster::GlPlaneRaster()
    : batches_("g2lf planes: batches", {{GL_COMPUTE_SHADER, g2lf_plane_batches_comp_glsl}}, {},
               {storage_buffer("plane_table", kPlaneTableBinding, Access::read),
                storage_buffer("batches", kPlaneBatchesBinding, Access::write)}),
      copy_("g2lf planes: batch copy", {{GL_COMPUTE_SHADER, g2lf_plane_copy_comp_glsl}}, {},
            {storage_buffer("batches", kPlaneBatchesBinding, Access::read),
             storage_buffer("batch_draw", kPlaneBatchDrawBinding, Access::write),
             storage_buffer("sorted_ids", kSplatValuesBinding, Access::read),
             storage_buffer("layers", kSplatLayersBinding, Access::read),
             storage_buffer("batch_ids", kPlaneBatchIdsBinding, Access::write),
             storage_buffer("batch_layers", kPlaneBatchLayersBinding, Access::write)}),
      convert_u8_(plane_convert_program("rgba8", true)),
      convert_f16_(plane_convert_program("rgba16f", false)),
      batch_draw_(sizeof(DrawArraysIndirect)) {}

size_t GlPlaneRaster::bytes() const {
  return accumulation_.bytes() + batch_commands_.bytes() + batch_draw_.bytes() + batch_ids_.bytes() +
         batch_layers_.bytes();
}

void GlPlaneRaster::ensure(const GlPlanes& planes, int batch_layers, size_t gaussians) {
  if (batch_layers == 0) {
    accumulation_ = Texture();  // nothing of the batched path is held while drawing directly
    batch_commands_ = Buffer();
    batch_ids_ = Buffer();
    batch_layers_ = Buffer();
    // Attached every frame: a reallocated plane array may reuse the old texture's name.
    direct_framebuffer_.attach(0, planes.texels);  // every layer: layered rendering
    if (!direct_ready_) direct_framebuffer_.finish(1);
    direct_ready_ = true;
    return;
  }
  if (!accumulation_.id() || accumulation_.width() != planes.width ||
      accumulation_.height() != planes.height || accumulation_.layers() != batch_layers) {
    accumulation_ = Texture();
    accumulation_ = Texture(GL_RGBA32F, planes.width, planes.height, batch_layers);
    const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // the convert pass keeps it so
    glClearTexImage(accumulation_.id(), 0, GL_RGBA, GL_FLOAT, empty);
    accumulation_framebuffer_ = Framebuffer();
    accumulation_framebuffer_.attach(0, accumulation_);
    accumulation_framebuffer_.finish(1);
  }
  const int batches = (planes.max_planes + batch_layers - 1) / batch_layers;
  batch_commands_.ensure(size_t(batches) * sizeof(PlaneBatch));
  batch_ids_.ensure(std::max<size_t>(gaussians, 1) * sizeof(uint32_t));
  batch_layers_.ensure(std::max<size_t>(gaussians, 1) * sizeof(uint32_t));
}

void GlPlaneRaster::run(const Buffer& records, const Buffer& sorted_ids, const Buffer& layers,
                        const Buffer& draw, size_t gaussians, int batch_layers, GlPlanes& planes) {
  if (batch_layers > 0 && planes.format == PlaneFormat::kRgba32f)
    throw std::logic_error("GlPlaneRaster: RGBA32F planes are drawn directly, not in batches");
  ensure(planes, batch_layers, gaussians);
  SplatRasterTarget target;
  target.image_size = {planes.width, planes.height};

  if (batch_layers == 0) {
    // Every layer to (C, T) = (0, 0, 0, 1), then all chunks in one draw, blended in the planes'
    // own format (GL keeps the primitive order per pixel: each plane's splats front to back).
    const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearTexImage(planes.texels.id(), 0, GL_RGBA, GL_FLOAT, empty);
    target.framebuffer = direct_framebuffer_.id();
    raster_.draw(records, sorted_ids, draw, target, &layers);
    return;
  }

  const GLuint batches = GLuint((planes.max_planes + batch_layers - 1) / batch_layers);
  glProgramUniform1ui(batches_.id(), batches_.uniform("batch_count"), batches);
  glProgramUniform1ui(batches_.id(), batches_.uniform("batch_layers"), GLuint(batch_layers));
  batches_.use();
  batches_.bind("plane_table", planes.table.buffer);
  batches_.bind("batches", batch_commands_);
  batches_.dispatch((batches + kPlaneBatchesGroupSize - 1) / kPlaneBatchesGroupSize);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

  const Program& convert = planes.format == PlaneFormat::kRgba8 ? convert_u8_ : convert_f16_;
  glProgramUniform1ui(copy_.id(), copy_.uniform("batch_layers"), GLuint(batch_layers));
  glProgramUniform1ui(convert.id(), convert.uniform("batch_layers"), GLuint(batch_layers));
  glProgramUniform2i(convert.id(), convert.uniform("plane_size"), planes.width, planes.height);
  target.framebuffer = accumulation_framebuffer_.id();
  for (GLuint b = 0; b < batches; ++b) {
    // The raster and the convert pass bind storage and images of their own: bind ours each time.
    glProgramUniform1ui(copy_.id(), copy_.uniform("batch"), b);
    copy_.use();
    copy_.bind("batches", batch_commands_);
    copy_.bind("batch_draw", batch_draw_);
    copy_.bind("sorted_ids", sorted_ids);
    copy_.bind("layers", layers);
    copy_.bind("batch_ids", batch_ids_);
    copy_.bind("batch_layers", batch_layers_);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, batch_commands_.id());
    copy_.dispatch_indirect(GLintptr(b * sizeof(PlaneBatch)));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

    raster_.draw(records, batch_ids_, batch_draw_, target, &batch_layers_);

    glProgramUniform1ui(convert.id(), convert.uniform("batch"), b);
    convert.use();
    convert.bind("plane_table", planes.table.buffer);
    convert.bind("accumulation", accumulation_);
    convert.bind("planes", planes.texels);
    convert.dispatch((GLuint(planes.width) + kPlaneGroupWidth - 1) / kPlaneGroupWidth,
                     (GLuint(planes.height) + kPlaneGroupHeight - 1) / kPlaneGroupHeight, GLuint(batch_layers));
    // The reset accumulation is drawn into next; the planes are fetched by the swizzle; the
    // batch buffers are rewritten by the next copy.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  }
  check_gl("G2LF planes in batches");
}

}  // namespace lfd::gpu
