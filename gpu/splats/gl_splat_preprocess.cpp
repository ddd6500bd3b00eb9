#include "gpu/splats/gl_splat_preprocess.hpp"

#include <algorithm>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/splats/shaders/splat_preprocess.comp.glsl.hpp"

namespace lfd::gpu {

void SplatBuffers::ensure(size_t gaussians) {
  if (gaussians <= capacity && draw.bytes()) return;
  const size_t n = std::max<size_t>(gaussians, 1);
  records.ensure(n * sizeof(SplatRecord));
  keys.ensure(n * 4);
  values.ensure(n * 4);
  draw.ensure(sizeof(DrawArraysIndirect));
  depth_range.ensure(2 * sizeof(uint32_t));
  capacity = n;
}

GlSplatPreprocess::GlSplatPreprocess() {
  program_ = Program("splat preprocess", {{GL_COMPUTE_SHADER, splat_preprocess_comp_glsl}}, {},
                     {storage_buffer("positions", kScenePositionsBinding, Access::read),
                      storage_buffer("scales", kSceneScalesBinding, Access::read),
                      storage_buffer("rotations", kSceneRotationsBinding, Access::read),
                      storage_buffer("sh", kSceneShBinding, Access::read),
                      storage_buffer("records", kSplatRecordsBinding, Access::write),
                      storage_buffer("keys", kSplatKeysBinding, Access::write),
                      storage_buffer("values", kSplatValuesBinding, Access::write),
                      storage_buffer("draw", kSplatDrawBinding, Access::read_write),
                      storage_buffer("depth_range", kSplatDepthRangeBinding, Access::read_write)});
}

void GlSplatPreprocess::run(const GlScene& scene, const render::Camera& camera,
                            const render::RasterSettings& settings, SplatBuffers& buffers) const {
  buffers.ensure(scene.size());
  const DrawArraysIndirect reset{4, 0, 0, 0};
  buffers.draw.upload(&reset, sizeof(reset));
  const uint32_t empty_range[2] = {0xFFFFFFFFu, 0u};
  buffers.depth_range.upload(empty_range, sizeof(empty_range));
  if (scene.size() == 0) return;

  const int requested = settings.sh_degree < 0 ? scene.sh_degree() : settings.sh_degree;
  const int degree = std::min(requested, scene.sh_degree());
  const glm::vec3 sh_origin = settings.sh_origin.value_or(camera.position_world);
  const GLuint p = program_.id();
  glProgramUniform1ui(p, program_.uniform("gaussian_count"), GLuint(scene.size()));
  glProgramUniformMatrix3fv(p, program_.uniform("world_to_camera"), 1, GL_FALSE,
                            glm::value_ptr(camera.world_to_camera));
  glProgramUniform3fv(p, program_.uniform("camera_position"), 1, glm::value_ptr(camera.position_world));
  glProgramUniform2f(p, program_.uniform("tan_half_fov"), camera.tan_half_fov_x(), camera.tan_half_fov_y());
  glProgramUniform2f(p, program_.uniform("focal_px"), camera.focal_x_px(), camera.focal_y_px());
  glProgramUniform2f(p, program_.uniform("shift_ndc"), camera.shift_x_ndc, camera.shift_y_ndc);
  glProgramUniform2i(p, program_.uniform("image_size"), camera.width, camera.height);
  glProgramUniform2i(p, program_.uniform("tile_grid"), (camera.width + render::kTileSize - 1) / render::kTileSize,
                     (camera.height + render::kTileSize - 1) / render::kTileSize);
  glProgramUniform1f(p, program_.uniform("dilation_px2"), settings.dilation_px2);
  glProgramUniform1f(p, program_.uniform("scale_modifier"), settings.scale_modifier);
  glProgramUniform1i(p, program_.uniform("sh_degree"), degree);
  glProgramUniform1i(p, program_.uniform("sh_stride"), scene.sh_vec4_stride());
  glProgramUniform3fv(p, program_.uniform("sh_origin"), 1, glm::value_ptr(sh_origin));

  program_.use();
  program_.bind("positions", scene.positions());
  program_.bind("scales", scene.scales());
  program_.bind("rotations", scene.rotations());
  program_.bind("sh", scene.sh());
  program_.bind("records", buffers.records);
  program_.bind("keys", buffers.keys);
  program_.bind("values", buffers.values);
  program_.bind("draw", buffers.draw);
  program_.bind("depth_range", buffers.depth_range);
  program_.dispatch_1d(scene.size(), kSplatPreprocessGroupSize);
  // What the consumers read: the sort (storage), the indirect draw (command), downloads (update).
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("the splat preprocess");
}

}  // namespace lfd::gpu
