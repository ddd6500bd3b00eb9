#include "gpu/voxels/gl_voxel_tile_raster.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/gl/gl_fault.hpp"
#include "gpu/gl/gl_limits.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/voxels/shaders/voxel_tile_keys.comp.glsl.hpp"
#include "gpu/voxels/shaders/voxel_tile_march.comp.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

static_assert(sizeof(VoxelTileView) == 96, "VoxelTileView is std430: packed floats");
static_assert(sizeof(VoxelTileRange) == 16, "VoxelTileRange is std430: packed uints");

Program keys_program(KeyStep step, TileImages images) {
  const std::string label = std::string("voxel tiles: ") + (step == KeyStep::kEmit ? "keys" : "counts") +
                            (images == TileImages::kPlanes ? " (planes)" : "");
  // What the pass reads and writes (docs/gpu.md "Binding points"): the voxels in their octant
  // orders, the images and runs, the counts; writing, the keys and values; for planes, each
  // ordered voxel's chunk.
  const bool emit = step == KeyStep::kEmit;
  std::vector<Binding> bindings = {storage_buffer("boxes", kVoxelBoxesBinding, Access::read),
                                   storage_buffer("order", kVoxelOrderBinding, Access::read),
                                   storage_buffer("views", kVoxelTileViewsBinding, Access::read),
                                   storage_buffer("runs", kVoxelTileRangesBinding, Access::read),
                                   tile_counts(emit ? Access::read : Access::write)};
  if (emit) bindings.push_back(tile_keys(Access::write)), bindings.push_back(tile_values(Access::write));
  if (images == TileImages::kPlanes) bindings.push_back(storage_buffer("chunk_of", kVoxelChunkOfBinding, Access::read));
  return Program(label, {{GL_COMPUTE_SHADER, voxel_tile_keys_comp_glsl}}, key_pass_defines(step, images),
                 std::move(bindings));
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
    : count_(keys_program(KeyStep::kCount, TileImages::kViews)),
      emit_(keys_program(KeyStep::kEmit, TileImages::kViews)),
      count_planes_(keys_program(KeyStep::kCount, TileImages::kPlanes)),
      emit_planes_(keys_program(KeyStep::kEmit, TileImages::kPlanes)),
      march_("voxel tiles: march", {{GL_COMPUTE_SHADER, voxel_tile_march_comp_glsl}}, {},
             {storage_buffer("boxes", kVoxelBoxesBinding, Access::read),
              storage_buffer("densities", kVoxelDensitiesBinding, Access::read),
              storage_buffer("sh", kSceneShBinding, Access::read), tile_values(Access::read),
              tile_ranges(Access::read), tile_work(Access::read), tile_state(Access::read),
              storage_buffer("views", kVoxelTileViewsBinding, Access::read),
              storage_buffer("runs", kVoxelTileRangesBinding, Access::read),
              image("target", kVoxelTileTargetImage, Access::read_write)}) {
  fail_if_faulted(GlFault::kComputeRaster, "voxel tiles");  // a driver that cannot build the path (tests)
  device_pass_limit_ = size_t(gl_limits().storage_block_bytes);
}

size_t GlVoxelTileRaster::pass_limit() const {
  if (pass_limit_ > 0) return pass_limit_;
  return device_pass_limit_;
}

void GlVoxelTileRaster::upload_views(std::span<const render::Camera> cameras, const glm::vec3* sh_origin) {
  std::vector<VoxelTileView> views;
  views.reserve(cameras.size());
  for (const render::Camera& c : cameras) views.push_back(voxel_tile_view(c, sh_origin ? *sh_origin : c.position_world));
  views_.ensure(std::max<size_t>(views.size(), 1) * sizeof(VoxelTileView));
  if (!views.empty()) views_.upload(views.data(), views.size() * sizeof(VoxelTileView));
}

bool GlVoxelTileRaster::make_keys(const GlVoxelScene& scene, glm::ivec2 image_size, std::span<const Run> runs,
                                  const Buffer& order, const Buffer* chunk_of, int plane_capacity, uint32_t pass) {
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
  if (items >= (uint64_t(1) << 32)) throw std::length_error("voxel tile raster: over 2^32 items a pass");
  const uint64_t slots = uint64_t(chunk_of ? plane_capacity : 1) * uint64_t(run_count_) * uint64_t(tile_grid_.x) *
                         uint64_t(tile_grid_.y);
  if (slots >= (uint64_t(1) << 32)) throw std::length_error("voxel tile raster: over 2^32 (image, octant, tile) slots");
  if (items == 0) {  // the pass's total is 0 all the same (the scan of no items writes it)
    keys_.scan_to_capacity(0, capacity_.for_pass(1));
    capacity_.record(keys_, pass);
    return false;
  }
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
  Buffer& counts = keys_.counts(items);
  const auto bind_inputs = [&](const Program& program) {
    program.bind("boxes", scene.boxes());
    program.bind("order", order);
    if (chunk_of) program.bind("chunk_of", *chunk_of);
    program.bind("views", views_);
    program.bind("runs", runs_);
    program.bind("tile_counts", counts);
  };
  count.use();
  bind_inputs(count);
  count.dispatch_1d(items, int(kVoxelTileItemsGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  keys_.scan_to_capacity(uint32_t(items), capacity_.for_pass(uint32_t(items)));
  glProgramUniform1ui(emit.id(), emit.uniform("key_capacity"), keys_.capacity());
  emit.use();
  bind_inputs(emit);
  keys_.bind(emit);  // the keys and values it writes
  emit.dispatch_1d(items, int(kVoxelTileItemsGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  keys_.sort_and_find_ranges_to_capacity(uint32_t(slots));
  capacity_.record(keys_, pass);
  return true;
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
  glProgramUniform1ui(p, march_.uniform("key_capacity"), keys_.capacity());
  march_.use();
  march_.bind("boxes", scene_->boxes());
  march_.bind("densities", scene_->densities());
  march_.bind("sh", scene_->sh());
  keys_.bind(march_);
  march_.bind("views", views_);
  march_.bind("runs", runs_);
  march_.bind("target", target);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // a clear or an earlier pass wrote the target
  if (slot_run == 0)
    keys_.dispatch_work(march_);
  else
    march_.dispatch_groups(slot_run);  // one group a slot
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("the voxel tile raster");
}

void GlVoxelTileRaster::render_views(const GlVoxelScene& scene, std::span<const render::Camera> cameras,
                                     const Texture& target, int cols) {
  planes_ready_ = false;
  passes_ = redrawn_ = 0;
  items_ = keys_total_ = 0;
  if (cameras.empty() || scene.size() == 0) return;
  if (cols < 1) throw std::invalid_argument("voxel tile raster: cols must be at least 1");
  for (const render::Camera& c : cameras)
    if (c.width != cameras[0].width || c.height != cameras[0].height)
      throw std::invalid_argument("voxel tile raster: views of different sizes");
  upload_views(cameras, nullptr);
  // Passes of consecutive views whose items' counts fit the limit (4 bytes an item); the keys
  // are known after the frame (a pass whose keys outgrow the limit is drawn again in halves).
  const size_t max_items = pass_limit() / 4, n = scene.size();
  const auto view_items = [&](size_t view) { return size_t(std::popcount(octants_in_view(cameras[view]))) * n; };
  const auto views = [&](size_t first, size_t count) {
    ViewPass pass{.first = first, .count = count, .items = 0};
    for (size_t view = first; view < first + count; ++view) pass.items += view_items(view);
    return pass;
  };
  std::vector<ViewPass> todo;
  for (size_t first = 0; first < cameras.size();) {
    ViewPass pass{.first = first, .count = 0, .items = 0};
    while (first + pass.count < cameras.size()) {
      const size_t items = view_items(first + pass.count);
      if (items > max_items)
        throw_input_error("--raster compute: {} voxels seen in {} octants need {:.0f} MiB of tile counts a view, over "
                          "the GPU's largest storage buffer ({:.0f} MiB); use --raster hardware",
                          n, items / n, double(items) * 4.0 / 1048576.0, double(pass_limit()) / 1048576.0);
      if (pass.count > 0 && pass.items + items > max_items) break;
      pass.items += items;
      ++pass.count;
    }
    todo.push_back(pass);
    first += pass.count;
  }
  // Every pass issued, then the frame's one read; the passes whose keys did not fit (they marched
  // nothing) go again with the capacity grown, those whose keys outgrow the limit in halves.
  const uint32_t key_limit = uint32_t(std::min<size_t>(max_items, UINT32_MAX));
  const glm::ivec2 size(cameras[0].width, cameras[0].height);
  while (!todo.empty()) {
    capacity_.set_keys(std::min(capacity_.keys(), key_limit));
    for (size_t p = 0; p < todo.size(); ++p) render_view_pass(scene, cameras, todo[p], uint32_t(p), target, cols);
    const uint32_t capacity = capacity_.keys();  // what the passes wrote to (a key an item the first time)
    const GlKeyCapacity::FrameKeys frame = capacity_.read_frame(uint32_t(todo.size()), key_limit);
    std::vector<ViewPass> again;
    for (size_t p = 0; p < todo.size(); ++p) {
      const ViewPass& pass = todo[p];
      if (frame.totals[p] <= capacity) {
        if (frame.totals[p] == 0) continue;  // nothing marched
        ++passes_;
        items_ += pass.items;
        keys_total_ += frame.totals[p];
        continue;
      }
      ++redrawn_;
      if (frame.totals[p] <= key_limit) {
        again.push_back(pass);
        continue;
      }
      if (pass.count == 1)
        throw_input_error("--raster compute: one {}x{} view of {} voxels has more tile keys than the GPU's largest "
                          "storage buffer holds ({:.0f} MiB); use --raster hardware",
                          size.x, size.y, n, double(pass_limit()) / 1048576.0);
      again.push_back(views(pass.first, pass.count / 2));
      again.push_back(views(pass.first + pass.count / 2, pass.count - pass.count / 2));
    }
    todo = std::move(again);
  }
}

void GlVoxelTileRaster::render_view_pass(const GlVoxelScene& scene, std::span<const render::Camera> cameras,
                                         const ViewPass& views, uint32_t pass, const Texture& target, int cols) {
  const uint32_t n = uint32_t(scene.size());
  std::vector<Run> runs;
  for (size_t view = views.first; view < views.first + views.count; ++view) {
    const uint32_t octants = octants_in_view(cameras[view]);
    for (uint32_t octant = 0; octant < 8; ++octant)
      if (octants & (1u << octant)) runs.push_back({uint32_t(view), octant, octant * n, n});
  }
  const glm::ivec2 size(cameras[0].width, cameras[0].height);
  if (make_keys(scene, size, runs, scene.order_buffer(), nullptr, 0, pass))
    march(target, glm::ivec2(0), cols, int(cameras.size()), 0, 0);
}

void GlVoxelTileRaster::render_view(const GlVoxelScene& scene, const render::Camera& camera,
                                    const glm::vec3& sh_origin, const Buffer& order, const VoxelOrderRanges& ranges,
                                    const Texture& target, glm::ivec2 origin) {
  planes_ready_ = false;
  upload_views({&camera, 1}, &sh_origin);
  std::vector<Run> runs;
  const uint32_t octants = octants_in_view(camera);
  for (uint32_t octant = 0; octant < 8; ++octant)
    if (octants & (1u << octant)) runs.push_back({0, octant, ranges[octant].offset, ranges[octant].count});
  if (make_keys(scene, {camera.width, camera.height}, runs, order, nullptr, 0, plane_passes_++))
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
  planes_ready_ =
      make_keys(scene, {camera.width, camera.height}, runs, orders, &chunk_of, plane_capacity, plane_passes_++);
}

void GlVoxelTileRaster::render_plane(int plane, const Texture& target) {
  if (!planes_ready_) return;  // no voxel has a key: every plane stays empty
  const uint32_t run = uint32_t(run_count_) * uint32_t(tile_grid_.x * tile_grid_.y);
  march(target, glm::ivec2(0), 1, 1, uint32_t(plane) * run, run);
}

bool GlVoxelTileRaster::planes_outgrew_capacity() {
  const GlKeyCapacity::FrameKeys frame = capacity_.read_frame(plane_passes_);
  plane_passes_ = 0;
  redrawn_ = int(frame.overflowed.size());
  return !frame.overflowed.empty();
}

}  // namespace lfd::gpu
