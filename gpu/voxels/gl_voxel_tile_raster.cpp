#include "gpu/voxels/gl_voxel_tile_raster.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/splats/gl_scene.hpp"
#include "gpu/voxels/shaders/voxel_tile_keys.comp.glsl.hpp"
#include "gpu/voxels/shaders/voxel_tile_march.comp.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

static_assert(sizeof(VoxelTileView) == 96, "VoxelTileView is std430: packed floats");
static_assert(sizeof(VoxelTileRange) == 16, "VoxelTileRange is std430: packed uints");

Program keys_program(bool emit, bool planes) {
  const std::string label = std::string("voxel tiles: ") + (emit ? "keys" : "counts") + (planes ? " (planes)" : "");
  return Program(label, {{GL_COMPUTE_SHADER, voxel_tile_keys_comp_glsl}},
                 {std::string("EMIT ") + (emit ? "1" : "0"), std::string("PLANES ") + (planes ? "1" : "0")});
}

// The image's uniforms (gpu/voxels/shaders/voxel_tile_view.glsl); tile_grid where the pass reads it.
void set_images(const Program& program, glm::ivec2 image_size, glm::ivec2 tile_grid, int run_count,
                bool with_tile_grid) {
  const GLuint p = program.id();
  glProgramUniform2i(p, program.uniform("image_size"), image_size.x, image_size.y);
  glProgramUniform1i(p, program.uniform("run_count"), run_count);
  if (with_tile_grid) glProgramUniform2i(p, program.uniform("tile_grid"), tile_grid.x, tile_grid.y);
}

glm::ivec2 tile_grid_of(glm::ivec2 image_size) {
  return {(image_size.x + int(kTileSide) - 1) / int(kTileSide), (image_size.y + int(kTileSide) - 1) / int(kTileSide)};
}

}  // namespace

VoxelTileView voxel_tile_view(const render::Camera& camera, const glm::vec3& sh_origin) {
  VoxelTileView v;
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) v.world_to_camera[4 * col + row] = camera.world_to_camera[col][row];
  for (int k = 0; k < 3; ++k) {
    v.position[k] = camera.position_world[k];
    v.sh_origin[k] = sh_origin[k];
  }
  v.tan_half_fov[0] = camera.tan_half_fov_x();
  v.tan_half_fov[1] = camera.tan_half_fov_y();
  v.shift_ndc[0] = camera.shift_x_ndc;
  v.shift_ndc[1] = camera.shift_y_ndc;
  return v;
}

GlVoxelTileRaster::GlVoxelTileRaster()
    : count_(keys_program(false, false)),
      emit_(keys_program(true, false)),
      count_planes_(keys_program(false, true)),
      emit_planes_(keys_program(true, true)),
      march_("voxel tiles: march", {{GL_COMPUTE_SHADER, voxel_tile_march_comp_glsl}}) {}

size_t GlVoxelTileRaster::pass_limit() const {
  if (pass_limit_ > 0) return pass_limit_;
  GLint64 block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
  return size_t(block);
}

void GlVoxelTileRaster::upload_views(std::span<const render::Camera> cameras, const glm::vec3* sh_origin) {
  std::vector<VoxelTileView> views;
  views.reserve(cameras.size());
  for (const render::Camera& c : cameras) views.push_back(voxel_tile_view(c, sh_origin ? *sh_origin : c.position_world));
  views_.ensure(std::max<size_t>(views.size(), 1) * sizeof(VoxelTileView));
  if (!views.empty()) views_.upload(views.data(), views.size() * sizeof(VoxelTileView));
}

GlVoxelTileRaster::Keys GlVoxelTileRaster::make_keys(const GlVoxelScene& scene, glm::ivec2 image_size,
                                                     std::span<const Run> runs, const Buffer& order,
                                                     const Buffer* chunk_of, int plane_capacity, size_t key_limit) {
  scene_ = &scene;
  image_size_ = image_size;
  tile_grid_ = tile_grid_of(image_size);
  std::vector<VoxelTileRange> table;
  uint64_t items = 0;
  for (const Run& run : runs) {
    if (run.count == 0) continue;
    items += run.count;
    table.push_back({.end_item = uint32_t(items), .order_offset = run.order_offset, .octant = run.octant,
                     .image = run.image});
  }
  run_count_ = int(table.size());
  last_items_ = last_keys_ = 0;
  if (items == 0) return Keys::kNone;
  if (items >= (uint64_t(1) << 32)) throw std::length_error("voxel tile raster: over 2^32 items a pass");
  const uint64_t slots = uint64_t(chunk_of ? plane_capacity : 1) * uint64_t(run_count_) * uint64_t(tile_grid_.x) *
                         uint64_t(tile_grid_.y);
  if (slots >= (uint64_t(1) << 32)) throw std::length_error("voxel tile raster: over 2^32 (image, octant, tile) slots");
  runs_.ensure(table.size() * sizeof(VoxelTileRange));
  runs_.upload(table.data(), table.size() * sizeof(VoxelTileRange));

  const Program& count = chunk_of ? count_planes_ : count_;
  const Program& emit = chunk_of ? emit_planes_ : emit_;
  for (const Program* program : {&count, &emit}) {
    set_images(*program, image_size_, tile_grid_, run_count_, program == &emit);
    const GLuint p = program->id();
    glProgramUniform1ui(p, program->uniform("item_count"), uint32_t(items));
    if (chunk_of) glProgramUniform1ui(p, program->uniform("plane_capacity"), GLuint(plane_capacity));
  }
  const auto bind_inputs = [&] {
    scene.bind();
    order.bind_storage(kVoxelOrderBinding);
    if (chunk_of) chunk_of->bind_storage(kVoxelChunkOfBinding);
    views_.bind_storage(kVoxelTileViewsBinding);
    runs_.bind_storage(kVoxelTileRangesBinding);
    keys_.counts(items).bind_storage(kTileCountsBinding);
  };
  bind_inputs();
  count.use();
  count.dispatch_1d(items, int(kVoxelTileItemsGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const uint32_t total = keys_.scan(uint32_t(items));
  last_items_ = uint32_t(items);
  last_keys_ = total;
  if (total == 0) return Keys::kNone;
  if (key_limit > 0 && size_t(total) > key_limit) return Keys::kOverLimit;
  bind_inputs();
  keys_.keys().bind_storage(kTileKeysBinding);
  keys_.values().bind_storage(kTileValuesBinding);
  emit.use();
  emit.dispatch_1d(items, int(kVoxelTileItemsGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  keys_.sort_and_find_ranges(total, uint32_t(slots));
  return Keys::kReady;
}

void GlVoxelTileRaster::march(const Texture& target, glm::ivec2 origin, int cols, int images, uint32_t slot_base,
                              uint32_t slot_run) {
  if (target.internal_format() != GL_RGBA32F) throw_input_error("voxel tile raster: the target must be GL_RGBA32F");
  const glm::ivec2 cells(std::min(cols, images), (images + cols - 1) / cols);
  const glm::ivec2 extent = origin + cells * image_size_;
  if (origin.x < 0 || origin.y < 0 || extent.x > target.width() || extent.y > target.height())
    throw_input_error("voxel tile raster: {} views of {}x{} in {} columns at ({}, {}) do not fit the {}x{} target",
                      images, image_size_.x, image_size_.y, cols, origin.x, origin.y, target.width(), target.height());
  const scene::VoxelScene& scene = scene_->scene();
  set_images(march_, image_size_, tile_grid_, run_count_, true);
  const GLuint p = march_.id();
  glProgramUniform2i(p, march_.uniform("viewport_origin"), origin.x, origin.y);
  glProgramUniform1i(p, march_.uniform("target_cols"), cols);
  glProgramUniform1i(p, march_.uniform("samples_per_voxel"), scene.samples_per_voxel);
  glProgramUniform1i(p, march_.uniform("sh_degree"), scene.sh_degree);
  glProgramUniform1i(p, march_.uniform("sh_stride"), sh_vec4_stride(scene.sh_degree));
  glProgramUniform1ui(p, march_.uniform("slot_base"), slot_base);
  glProgramUniform1ui(p, march_.uniform("slot_run"), slot_run);
  scene_->bind();
  keys_.bind();
  views_.bind_storage(kVoxelTileViewsBinding);
  runs_.bind_storage(kVoxelTileRangesBinding);
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

void GlVoxelTileRaster::draw_views(const GlVoxelScene& scene, std::span<const render::Camera> cameras,
                                   const Texture& target, int cols) {
  planes_ready_ = false;
  passes_ = 0;
  items_ = keys_total_ = 0;
  if (cameras.empty() || scene.size() == 0) return;
  if (cols < 1) throw std::invalid_argument("voxel tile raster: cols must be at least 1");
  for (const render::Camera& c : cameras)
    if (c.width != cameras[0].width || c.height != cameras[0].height)
      throw std::invalid_argument("voxel tile raster: views of different sizes");
  upload_views(cameras, nullptr);
  // Passes of consecutive views whose items' counts fit the limit (4 bytes an item); the keys
  // are known after the scan (draw_view_pass halves a pass whose keys do not fit).
  const size_t max_items = pass_limit() / 4, n = scene.size();
  size_t first = 0;
  while (first < cameras.size()) {
    size_t count = 0, items = 0;
    while (first + count < cameras.size()) {
      const size_t view_items = size_t(std::popcount(octants_in_view(cameras[first + count]))) * n;
      if (view_items > max_items)
        throw_input_error("--raster compute: {} voxels seen in {} octants need {:.0f} MiB of tile counts a view, over "
                          "the GPU's largest storage buffer ({:.0f} MiB); use --raster hardware",
                          n, view_items / n, double(view_items) * 4.0 / 1048576.0, double(pass_limit()) / 1048576.0);
      if (count > 0 && items + view_items > max_items) break;
      items += view_items;
      ++count;
    }
    draw_view_pass(scene, cameras, first, count, target, cols);
    first += count;
  }
}

void GlVoxelTileRaster::draw_view_pass(const GlVoxelScene& scene, std::span<const render::Camera> cameras,
                                       size_t first, size_t count, const Texture& target, int cols) {
  const uint32_t n = uint32_t(scene.size());
  std::vector<Run> runs;
  for (size_t view = first; view < first + count; ++view) {
    const uint32_t octants = octants_in_view(cameras[view]);
    for (uint32_t octant = 0; octant < 8; ++octant)
      if (octants & (1u << octant)) runs.push_back({uint32_t(view), octant, octant * n, n});
  }
  const size_t key_limit = pass_limit() / 4;
  const glm::ivec2 size(cameras[0].width, cameras[0].height);
  switch (make_keys(scene, size, runs, scene.order_buffer(), nullptr, 0, key_limit)) {
    case Keys::kNone: return;
    case Keys::kReady:
      march(target, glm::ivec2(0), cols, int(cameras.size()), 0, 0);
      ++passes_;
      items_ += last_items_;
      keys_total_ += last_keys_;
      return;
    case Keys::kOverLimit:
      if (count == 1)
        throw_input_error("--raster compute: one {}x{} view of {} voxels has more tile keys than the GPU's largest "
                          "storage buffer holds ({:.0f} MiB); use --raster hardware",
                          size.x, size.y, n, double(pass_limit()) / 1048576.0);
      draw_view_pass(scene, cameras, first, count / 2, target, cols);
      draw_view_pass(scene, cameras, first + count / 2, count - count / 2, target, cols);
      return;
  }
}

void GlVoxelTileRaster::draw(const GlVoxelScene& scene, const render::Camera& camera, const glm::vec3& sh_origin,
                             const Buffer& order, const VoxelOrderRanges& ranges, const Texture& target,
                             glm::ivec2 origin) {
  planes_ready_ = false;
  upload_views({&camera, 1}, &sh_origin);
  std::vector<Run> runs;
  const uint32_t octants = octants_in_view(camera);
  for (uint32_t octant = 0; octant < 8; ++octant)
    if (octants & (1u << octant)) runs.push_back({0, octant, ranges[octant].offset, ranges[octant].count});
  if (make_keys(scene, {camera.width, camera.height}, runs, order, nullptr, 0, 0) == Keys::kReady)
    march(target, origin, 1, 1, 0, 0);
}

void GlVoxelTileRaster::begin_planes(const GlVoxelScene& scene, const render::Camera& camera,
                                     const glm::vec3& sh_origin, const Buffer& orders, const Buffer& chunk_of,
                                     int plane_capacity) {
  // GlVoxelBinning's slots: the octants in view in octant order, scene.size() entries each.
  upload_views({&camera, 1}, &sh_origin);
  std::vector<Run> runs;
  const uint32_t n = uint32_t(scene.size()), octants = octants_in_view(camera);
  uint32_t slot = 0;
  for (uint32_t octant = 0; octant < 8; ++octant)
    if (octants & (1u << octant)) runs.push_back({0, octant, n * slot++, n});
  planes_ready_ = make_keys(scene, {camera.width, camera.height}, runs, orders, &chunk_of, plane_capacity, 0) ==
                  Keys::kReady;
}

void GlVoxelTileRaster::draw_plane(int plane, const Texture& target) {
  if (!planes_ready_) return;  // no voxel has a key: every plane stays empty
  const uint32_t run = uint32_t(run_count_) * uint32_t(tile_grid_.x * tile_grid_.y);
  march(target, glm::ivec2(0), 1, 1, uint32_t(plane) * run, run);
}

}  // namespace lfd::gpu
