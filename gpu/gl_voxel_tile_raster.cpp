#include "gpu/gl_voxel_tile_raster.hpp"

#include <array>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/gl_scene.hpp"
#include "gpu/shaders/voxel_tile_io.h"
#include "gpu/shaders/voxel_tile_keys.comp.glsl.hpp"
#include "gpu/shaders/voxel_tile_march.comp.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

Program keys_program(bool emit, bool planes) {
  const std::string label = std::string("voxel tiles: ") + (emit ? "keys" : "counts") + (planes ? " (planes)" : "");
  return Program(label, {{GL_COMPUTE_SHADER, voxel_tile_keys_comp_glsl}},
                 {std::string("EMIT ") + (emit ? "1" : "0"), std::string("PLANES ") + (planes ? "1" : "0")});
}

// The camera's uniforms (gpu/shaders/voxel_tile_view.glsl); tile_grid where the pass reads it.
void set_view(const Program& program, const render::Camera& camera, glm::ivec2 tile_grid, bool with_tile_grid) {
  const GLuint p = program.id();
  glProgramUniformMatrix3fv(p, program.uniform("world_to_camera"), 1, GL_FALSE, glm::value_ptr(camera.world_to_camera));
  glProgramUniform3fv(p, program.uniform("camera_position"), 1, glm::value_ptr(camera.position_world));
  glProgramUniform2f(p, program.uniform("tan_half_fov"), camera.tan_half_fov_x(), camera.tan_half_fov_y());
  glProgramUniform2f(p, program.uniform("shift_ndc"), camera.shift_x_ndc, camera.shift_y_ndc);
  glProgramUniform2i(p, program.uniform("image_size"), camera.width, camera.height);
  if (with_tile_grid) glProgramUniform2i(p, program.uniform("tile_grid"), tile_grid.x, tile_grid.y);
}

glm::ivec2 tile_grid_of(const render::Camera& camera) {
  return {(camera.width + int(kTileSide) - 1) / int(kTileSide), (camera.height + int(kTileSide) - 1) / int(kTileSide)};
}

}  // namespace

GlVoxelTileRaster::GlVoxelTileRaster()
    : count_(keys_program(false, false)),
      emit_(keys_program(true, false)),
      count_planes_(keys_program(false, true)),
      emit_planes_(keys_program(true, true)),
      march_("voxel tiles: march", {{GL_COMPUTE_SHADER, voxel_tile_march_comp_glsl}}) {}

bool GlVoxelTileRaster::make_keys(const GlVoxelScene& scene, const render::Camera& camera, const Buffer& order,
                                  const VoxelOrderRanges& ranges, const Buffer* chunk_of, int plane_capacity) {
  scene_ = &scene;
  camera_ = camera;
  tile_grid_ = tile_grid_of(camera);
  // The items: the ranges of the octants some pixel's ray takes, one after another.
  const uint32_t octants = octants_in_view(camera);
  std::array<GLuint, 8> end_item{}, offset{};
  range_octant_ = {};
  int& range_count = range_count_;
  range_count = 0;
  uint32_t items = 0;
  for (int octant = 0; octant < 8; ++octant) {
    const VoxelOrderRange& range = ranges[size_t(octant)];
    if (!(octants & (1u << octant)) || range.count == 0) continue;
    items += range.count;
    end_item[size_t(range_count)] = items;
    offset[size_t(range_count)] = range.offset;
    range_octant_[size_t(range_count)] = octant;
    ++range_count;
  }
  if (items == 0) return false;
  const uint32_t images = chunk_of ? uint32_t(plane_capacity) : 1u;
  const uint32_t slots = images * uint32_t(range_count) * uint32_t(tile_grid_.x * tile_grid_.y);

  const Program& count = chunk_of ? count_planes_ : count_;
  const Program& emit = chunk_of ? emit_planes_ : emit_;
  for (const Program* program : {&count, &emit}) {
    set_view(*program, camera, tile_grid_, program == &emit);
    const GLuint p = program->id();
    glProgramUniform1ui(p, program->uniform("item_count"), items);
    glProgramUniform1i(p, program->uniform("range_count"), range_count);
    glProgramUniform1uiv(p, program->uniform("range_end_item"), 8, end_item.data());
    glProgramUniform1uiv(p, program->uniform("range_offset"), 8, offset.data());
    glProgramUniform1iv(p, program->uniform("range_octant"), 8, range_octant_.data());
    if (chunk_of) glProgramUniform1ui(p, program->uniform("plane_capacity"), GLuint(plane_capacity));
  }
  const auto bind_inputs = [&] {
    scene.bind();
    order.bind_storage(kVoxelOrderBinding);
    if (chunk_of) chunk_of->bind_storage(kVoxelChunkOfBinding);
    keys_.counts(items).bind_storage(kTileCountsBinding);
  };
  bind_inputs();
  count.use();
  count.dispatch_1d(items, int(kVoxelTileItemsGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const uint32_t total = keys_.scan(items);
  if (total == 0) return false;
  bind_inputs();
  keys_.keys().bind_storage(kTileKeysBinding);
  keys_.values().bind_storage(kTileValuesBinding);
  emit.use();
  emit.dispatch_1d(items, int(kVoxelTileItemsGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  keys_.sort_and_find_ranges(total, slots);
  return true;
}

void GlVoxelTileRaster::march(const Texture& target, glm::ivec2 origin, uint32_t slot_base, uint32_t slot_run) {
  if (target.internal_format() != GL_RGBA32F) throw_input_error("voxel tile raster: the target must be GL_RGBA32F");
  if (origin.x < 0 || origin.y < 0 || origin.x + camera_.width > target.width() ||
      origin.y + camera_.height > target.height())
    throw_input_error("voxel tile raster: a {}x{} view at ({}, {}) does not fit the {}x{} target", camera_.width,
                      camera_.height, origin.x, origin.y, target.width(), target.height());
  const scene::VoxelScene& scene = scene_->scene();
  set_view(march_, camera_, tile_grid_, true);
  const GLuint p = march_.id();
  glProgramUniform2i(p, march_.uniform("viewport_origin"), origin.x, origin.y);
  glProgramUniform1i(p, march_.uniform("samples_per_voxel"), scene.samples_per_voxel);
  glProgramUniform1i(p, march_.uniform("sh_degree"), scene.sh_degree);
  glProgramUniform1i(p, march_.uniform("sh_stride"), sh_vec4_stride(scene.sh_degree));
  glProgramUniform1ui(p, march_.uniform("slot_base"), slot_base);
  glProgramUniform1ui(p, march_.uniform("slot_run"), slot_run);
  glProgramUniform1i(p, march_.uniform("range_count"), range_count_);
  glProgramUniform1iv(p, march_.uniform("range_octant"), 8, range_octant_.data());
  scene_->bind();
  keys_.bind();
  glBindImageTexture(kVoxelTileTargetImage, target.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // a clear or an earlier pass wrote the target
  march_.use();
  if (slot_run == 0)
    keys_.dispatch_work();
  else
    march_.dispatch_1d(slot_run, 1);  // one group a slot (spread over y past 65535)
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("the voxel tile raster");
}

void GlVoxelTileRaster::draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                             const Buffer& order, const VoxelOrderRanges& ranges, const Texture& target,
                             glm::ivec2 origin) {
  planes_ready_ = false;
  glProgramUniform3fv(march_.id(), march_.uniform("sh_origin"), 1, glm::value_ptr(sh_origin));
  if (make_keys(scene, camera, order, ranges, nullptr, 0)) march(target, origin, 0, 0);
}

void GlVoxelTileRaster::draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                             const Texture& target, glm::ivec2 origin) {
  VoxelOrderRanges ranges;
  const uint32_t n = uint32_t(scene.size());
  for (uint32_t octant = 0; octant < 8; ++octant) ranges[octant] = {octant * n, n};
  draw(scene, camera, sh_origin, scene.order_buffer(), ranges, target, origin);
}

void GlVoxelTileRaster::begin_planes(const GlVoxelScene& scene, const render::Camera& camera,
                                     const glm::vec3& sh_origin, const Buffer& orders, const Buffer& chunk_of,
                                     int plane_capacity) {
  // GlVoxelBinning's slots: the octants in view in octant order, scene.size() entries each.
  VoxelOrderRanges ranges;
  const uint32_t n = uint32_t(scene.size()), octants = octants_in_view(camera);
  uint32_t slot = 0;
  for (uint32_t octant = 0; octant < 8; ++octant)
    if (octants & (1u << octant)) ranges[octant] = {n * slot++, n};
  glProgramUniform3fv(march_.id(), march_.uniform("sh_origin"), 1, glm::value_ptr(sh_origin));
  planes_ready_ = make_keys(scene, camera, orders, ranges, &chunk_of, plane_capacity);
}

void GlVoxelTileRaster::draw_plane(int plane, const Texture& target) {
  if (!planes_ready_) return;  // no voxel has a key: every plane stays empty
  const uint32_t run = uint32_t(range_count_) * uint32_t(tile_grid_.x * tile_grid_.y);
  march(target, glm::ivec2(0), uint32_t(plane) * run, run);
}

}  // namespace lfd::gpu
