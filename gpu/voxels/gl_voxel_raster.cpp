#include "gpu/voxels/gl_voxel_raster.hpp"

#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/voxels/shaders/voxel_raster.frag.glsl.hpp"
#include "gpu/voxels/shaders/voxel_raster.vert.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

Program voxel_program() {
  return Program("voxel raster", {{GL_VERTEX_SHADER, voxel_raster_vert_glsl}, {GL_FRAGMENT_SHADER, voxel_raster_frag_glsl}},
                 {},
                 {storage_buffer("boxes", kVoxelBoxesBinding, Access::read),
                  storage_buffer("densities", kVoxelDensitiesBinding, Access::read),
                  storage_buffer("order", kVoxelOrderBinding, Access::read),
                  storage_buffer("sh", kSceneShBinding, Access::read),
                  storage_buffer("draws", kVoxelDrawsBinding, Access::read)});
}

}  // namespace

GlVoxelRaster::GlVoxelRaster() : program_(voxel_program()), no_draws_(4 * sizeof(uint32_t)) {}

uint32_t GlVoxelRaster::set_view(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                                 const Buffer& order, const SplatRasterTarget& target) const {
  if (camera.width != target.image_size.x || camera.height != target.image_size.y)
    throw_input_error("voxel raster: the camera is {}x{}, the target {}x{}", camera.width, camera.height,
                      target.image_size.x, target.image_size.y);
  const GLuint p = program_.id();
  glProgramUniformMatrix3fv(p, program_.uniform("world_to_camera"), 1, GL_FALSE,
                            glm::value_ptr(camera.world_to_camera));
  glProgramUniform3fv(p, program_.uniform("camera_position"), 1, glm::value_ptr(camera.position_world));
  glProgramUniform2f(p, program_.uniform("tan_half_fov"), camera.tan_half_fov_x(), camera.tan_half_fov_y());
  glProgramUniform2f(p, program_.uniform("shift_ndc"), camera.shift_x_ndc, camera.shift_y_ndc);
  glProgramUniform2i(p, program_.uniform("image_size"), camera.width, camera.height);
  glProgramUniform2f(p, program_.uniform("viewport_origin"), float(target.viewport_origin.x),
                     float(target.viewport_origin.y));
  glProgramUniform3fv(p, program_.uniform("sh_origin"), 1, glm::value_ptr(sh_origin));
  glProgramUniform1i(p, program_.uniform("sh_degree"), scene.scene().sh_degree);
  glProgramUniform1i(p, program_.uniform("sh_stride"), sh_vec4_stride(scene.scene().sh_degree));
  glProgramUniform1i(p, program_.uniform("samples_per_voxel"), scene.scene().samples_per_voxel);
  program_.bind("boxes", scene.boxes());
  program_.bind("densities", scene.densities());
  program_.bind("sh", scene.sh());
  program_.bind("order", order);
  return octants_in_view(camera);
}

void GlVoxelRaster::draw_octants(uint32_t octants, const SplatRasterTarget& target,
                                 const std::function<void(int octant)>& issue) const {
  begin_raster_target(target);
  glBindVertexArray(vertex_array_.id());
  program_.use();
  enable_front_to_back_blend();
  for (int octant = 0; octant < 8; ++octant)
    if (octants & (1u << octant)) issue(octant);
  end_raster_target();
  check_gl("drawing voxels");
}

void GlVoxelRaster::draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                         const Buffer& order, const VoxelOrderRanges& ranges, const SplatRasterTarget& target) const {
  const GLuint p = program_.id();
  glProgramUniform1i(p, program_.uniform("draw_command"), -1);
  program_.bind("draws", no_draws_);  // draw_command -1: the shader reads no command
  draw_octants(set_view(scene, camera, sh_origin, order, target), target, [&](int octant) {
    const VoxelOrderRange& range = ranges[size_t(octant)];
    if (range.count == 0) return;
    glProgramUniform1ui(p, program_.uniform("order_offset"), range.offset);
    glProgramUniform1i(p, program_.uniform("octant"), octant);
    program_.draw_arrays(GL_TRIANGLE_STRIP, 0, 4, GLsizei(range.count));
  });
}

void GlVoxelRaster::begin_indirect(const GlVoxelScene& scene, const render::Camera& camera,
                                   const glm::vec3& sh_origin, const Buffer& order, const Buffer& draws,
                                   const SplatRasterTarget& target) {
  glProgramUniform1ui(program_.id(), program_.uniform("order_offset"), 0u);
  indirect_octants_ = set_view(scene, camera, sh_origin, order, target);
  program_.bind("draws", draws);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draws.id());
}

void GlVoxelRaster::draw_indirect(int plane, const SplatRasterTarget& target) const {
  const GLuint p = program_.id();
  draw_octants(indirect_octants_, target, [&](int octant) {
    const int command = int(kVoxelOctants) * plane + octant;
    glProgramUniform1i(p, program_.uniform("draw_command"), command);
    glProgramUniform1i(p, program_.uniform("octant"), octant);
    program_.draw_arrays_indirect(GL_TRIANGLE_STRIP, GLintptr(size_t(command) * 4 * sizeof(uint32_t)));
  });
}

void GlVoxelRaster::draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                         const SplatRasterTarget& target) const {
  VoxelOrderRanges ranges;
  const uint32_t n = uint32_t(scene.size());
  for (uint32_t octant = 0; octant < 8; ++octant) ranges[octant] = {octant * n, n};
  draw(scene, camera, sh_origin, scene.order_buffer(), ranges, target);
}

}  // namespace lfd::gpu
