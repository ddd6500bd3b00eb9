#include "gpu/splats/gl_splat_tile_raster.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/gl/gl_fault.hpp"
#include "gpu/gl/gl_limits.hpp"
#include "gpu/splats/gl_splat_preprocess.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/compute/shaders/radix_sort_io.h"
#include "gpu/splats/shaders/splat_tile_composite.comp.glsl.hpp"
#include "gpu/splats/shaders/splat_tile_huge.comp.glsl.hpp"
#include "gpu/splats/shaders/splat_tile_io.h"
#include "gpu/splats/shaders/splat_tile_keys.comp.glsl.hpp"
#include "gpu/splats/shaders/splat_tile_merge.comp.glsl.hpp"
#include "gpu/splats/shaders/splat_tile_split.comp.glsl.hpp"
#include "gpu/splats/shaders/splat_tile_preprocess.comp.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

static_assert(sizeof(TileViewCamera) == 112, "TileViewCamera is std430: packed floats");
static_assert(sizeof(TileHugeList) == kTileHugeListWords * 4 && offsetof(TileHugeList, groups_x) == 16);
static_assert(sizeof(TileSplitList) == kTileSplitListWords * 4 && offsetof(TileSplitList, merge_groups_x) == 16 &&
                  offsetof(TileSplitList, part_groups_x) == 32,
              "TileSplitList is std430: packed uints");
// The split list: its header, kTileSplatMaxParts split slots (uvec4), kTileSplatMaxParts parts (uvec2).
constexpr size_t kSplitSlotsOffset = sizeof(TileSplitList);
constexpr size_t kSplitPartsOffset = kSplitSlotsOffset + size_t(kTileSplatMaxParts) * 16;
constexpr size_t kSplitListBytes = kSplitPartsOffset + size_t(kTileSplatMaxParts) * 8;
constexpr size_t kPartialBytes = size_t(kTilePixels) * 16;  // a part's vec4 per pixel
static_assert(kTileSide == uint32_t(render::kTileSize), "the compute tiles are the reference's");

// What a key pass reads and writes (docs/gpu.md "Binding points"): the items and their counts;
// the small items' pass the item count and (counting) the huge list it fills, the huge items' pass
// that list; writing, the keys and values; for planes, each item's plane.
std::vector<Binding> key_bindings(bool huge, KeyStep step, TileImages images) {
  std::vector<Binding> b = {storage_buffer("records", kSplatRecordsBinding, Access::read),
                            storage_buffer("entries", kTileSplatEntriesBinding, Access::read),
                            tile_counts(step == KeyStep::kEmit && !huge ? Access::read : Access::read_write)};
  if (!huge) b.push_back(storage_buffer("kept", kTileSplatKeptBinding, Access::read));
  if (huge || step == KeyStep::kCount)
    b.push_back(storage_buffer("huge", kTileSplatHugeBinding, huge ? Access::read : Access::read_write));
  if (step == KeyStep::kEmit) b.push_back(tile_keys(Access::write)), b.push_back(tile_values(Access::write));
  if (images == TileImages::kPlanes) b.push_back(storage_buffer("layers", kTileSplatLayersBinding, Access::read));
  return b;
}

enum class KeyItems { kSmall, kHuge };  // splat_tile_keys, splat_tile_huge

Program keys_program(const char* label, KeyItems which, KeyStep step, TileImages images) {
  const bool huge = which == KeyItems::kHuge;
  const char* source = huge ? splat_tile_huge_comp_glsl : splat_tile_keys_comp_glsl;
  return Program(label, {{GL_COMPUTE_SHADER, source}}, key_pass_defines(step, images),
                 key_bindings(huge, step, images));
}

Binding split_list(Access access) { return storage_buffer("split", kTileSplatSplitBinding, access); }
Binding partials(Access access) { return storage_buffer("partials", kTileSplatPartialsBinding, access); }
Binding target_image() { return image("target", kTileSplatTargetImage, Access::write); }

const char* image_format_name(GLenum format) {
  switch (format) {
    case GL_RGBA32F: return "rgba32f";
    case GL_RGBA16F: return "rgba16f";
    case GL_RGBA8: return "rgba8";
    default: throw std::invalid_argument("compute tile rasterizer: the target must be RGBA32F, RGBA16F or RGBA8");
  }
}

TileViewCamera view_camera(const render::Camera& camera, const render::RasterSettings& settings) {
  TileViewCamera c;
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) c.world_to_camera[4 * col + row] = camera.world_to_camera[col][row];
  const glm::vec3 sh_origin = settings.sh_origin.value_or(camera.position_world);
  for (int k = 0; k < 3; ++k) {
    c.position[k] = camera.position_world[k];
    c.sh_origin[k] = sh_origin[k];
  }
  c.tan_half_fov[0] = camera.tan_half_fov_x();
  c.tan_half_fov[1] = camera.tan_half_fov_y();
  c.focal_px[0] = camera.focal_x_px();
  c.focal_px[1] = camera.focal_y_px();
  c.shift_ndc[0] = camera.shift_x_ndc;
  c.shift_ndc[1] = camera.shift_y_ndc;
  return c;
}

}  // namespace

GlSplatTileRaster::KeyPrograms::KeyPrograms(TileImages images)
    : count(keys_program("compute splats: count keys", KeyItems::kSmall, KeyStep::kCount, images)),
      emit(keys_program("compute splats: write keys", KeyItems::kSmall, KeyStep::kEmit, images)),
      huge_count(keys_program("compute splats: count huge keys", KeyItems::kHuge, KeyStep::kCount, images)),
      huge_emit(keys_program("compute splats: write huge keys", KeyItems::kHuge, KeyStep::kEmit, images)) {}

GlSplatTileRaster::GlSplatTileRaster()
    : preprocess_("compute splats: preprocess", {{GL_COMPUTE_SHADER, splat_tile_preprocess_comp_glsl}}, {},
                  {storage_buffer("positions", kScenePositionsBinding, Access::read),
                   storage_buffer("scales", kSceneScalesBinding, Access::read),
                   storage_buffer("rotations", kSceneRotationsBinding, Access::read),
                   storage_buffer("sh", kSceneShBinding, Access::read),
                   storage_buffer("records", kSplatRecordsBinding, Access::write),
                   storage_buffer("entry_keys", kTileSplatEntryKeysBinding, Access::write),
                   storage_buffer("entries", kTileSplatEntriesBinding, Access::write),
                   storage_buffer("views", kTileSplatViewsBinding, Access::read)}),
      split_("compute splats: split hot tiles", {{GL_COMPUTE_SHADER, splat_tile_split_comp_glsl}}, {},
             {tile_ranges(Access::read_write), tile_work(Access::read), tile_state(Access::read),
              split_list(Access::read_write)}),
      view_keys_(TileImages::kViews),
      plane_keys_(TileImages::kPlanes) {
  fail_if_faulted(GlFault::kComputeRaster, "compute splats");  // a driver that cannot build the path (tests)
  device_pass_limit_ = size_t(gl_limits().storage_block_bytes);
}

// The defines of a program that includes splat_tile_target.glsl.
std::vector<std::string> target_defines(GLenum format, TileImages images) {
  const bool planes = images == TileImages::kPlanes;
  const bool quantize = planes && format == GL_RGBA8;
  return {std::string("TARGET_ARRAY ") + (planes ? "1" : "0"),
          std::string("TARGET_FORMAT ") + image_format_name(format),
          std::string("QUANTIZE_U8 ") + (quantize ? "1" : "0")};
}

const Program& GlSplatTileRaster::composite_program(GLenum format, TileImages images, SlotShare share) {
  const bool part = share == SlotShare::kSplitParts;
  if (part) format = GL_RGBA32F, images = TileImages::kViews;  // parts write partials, not the target
  const bool planes = images == TileImages::kPlanes;
  auto it = composite_.find({format, images, share});
  if (it == composite_.end()) {
    std::vector<std::string> defines = target_defines(format, images);
    defines.push_back(std::string("SPLIT_PART ") + (part ? "1" : "0"));
    const std::string label = part ? std::string("compute splats: composite split parts")
                                   : std::string("compute splats: composite into ") + (planes ? "planes " : "views ") +
                                         image_format_name(format);
    // A split part blends a run of a slot's keys into partials; a whole slot its range into the
    // target, planes from the work list.
    std::vector<Binding> bindings = {storage_buffer("records", kSplatRecordsBinding, Access::read),
                                     tile_values(Access::read)};
    if (part) {
      bindings.push_back(split_list(Access::read));
      bindings.push_back(partials(Access::write));
    } else {
      bindings.push_back(tile_ranges(Access::read));
      if (planes) bindings.push_back(tile_work(Access::read)), bindings.push_back(tile_state(Access::read));
      bindings.push_back(target_image());
    }
    it = composite_
             .emplace(std::tuple(format, images, share),
                      Program(label, {{GL_COMPUTE_SHADER, splat_tile_composite_comp_glsl}}, defines,
                              std::move(bindings)))
             .first;
  }
  return it->second;
}

const Program& GlSplatTileRaster::merge_program(GLenum format, TileImages images) {
  auto it = merge_.find({format, images});
  if (it == merge_.end())
    it = merge_
             .emplace(std::pair(format, images),
                      Program(std::string("compute splats: merge split tiles into ") +
                                  (images == TileImages::kPlanes ? "planes " : "views ") + image_format_name(format),
                              {{GL_COMPUTE_SHADER, splat_tile_merge_comp_glsl}}, target_defines(format, images),
                              {storage_buffer("records", kSplatRecordsBinding, Access::read),
                               tile_values(Access::read), split_list(Access::read), partials(Access::read),
                               target_image()}))
             .first;
  return it->second;
}

void GlSplatTileRaster::set_target_uniforms(const Program& program, const TargetUniforms& t) {
  const GLuint p = program.id();
  glProgramUniform2i(p, program.uniform("image_size"), t.image_size.x, t.image_size.y);
  glProgramUniform2i(p, program.uniform("tile_grid"), t.tile_grid.x, t.tile_grid.y);
  if (!t.views) return;
  glProgramUniform1ui(p, program.uniform("first_view"), t.first_view);
  glProgramUniform1i(p, program.uniform("cols"), t.views->cols);
  glProgramUniform2i(p, program.uniform("cell_size"), t.views->cell_size.x, t.views->cell_size.y);
  glProgramUniform3fv(p, program.uniform("background"), 1, glm::value_ptr(t.views->background));
  glProgramUniform1i(p, program.uniform("keep_transmittance"), t.views->alpha == TargetAlpha::kTransmittance ? 1 : 0);
}

bool GlSplatTileRaster::split_slots(uint32_t keys, uint32_t slots) {
  split_ran_ = split_keys_ > 0 && keys > split_keys_;
  if (!split_ran_) return false;
  // Parts handed out: sum over split slots of ceil(L / K) <= keys / K + (split slots <= keys / K).
  const size_t parts = std::min<size_t>(kTileSplatMaxParts, 2 * size_t(keys) / split_keys_ + 1);
  split_list_.ensure(kSplitListBytes);
  partials_.ensure(parts * kPartialBytes);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the last frame's split pass wrote the list
  const TileSplitList none{};
  split_list_.upload(&none, sizeof(none));
  const uint32_t no_part = 0xFFFFFFFFu;
  glClearNamedBufferSubData(split_list_.id(), GL_R32UI, GLintptr(kSplitPartsOffset),
                            GLsizeiptr(kSplitListBytes - kSplitPartsOffset), GL_RED_INTEGER, GL_UNSIGNED_INT, &no_part);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform1ui(split_.id(), split_.uniform("split_keys"), split_keys_);
  split_.use();
  tiles_.bind(split_);
  split_.bind("split", split_list_);
  split_.dispatch_1d(slots, int(kTileSplatSplitGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  tiles_.write_dispatch(split_list_, offsetof(TileSplitList, slots) / 4, offsetof(TileSplitList, merge_groups_x) / 4);
  tiles_.write_dispatch(split_list_, offsetof(TileSplitList, parts) / 4, offsetof(TileSplitList, part_groups_x) / 4);
  return true;
}

void GlSplatTileRaster::composite_split(GLenum format, TileImages images, const TargetUniforms& target,
                                        const Buffer& records, const Texture& target_texture) {
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // the merge writes after the whole-slot pass
  const Program& parts = composite_program(format, images, SlotShare::kSplitParts);
  set_target_uniforms(parts, {.image_size = target.image_size, .tile_grid = target.tile_grid});
  glProgramUniform1ui(parts.id(), parts.uniform("split_keys"), split_keys_);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, split_list_.id());
  parts.use();
  tiles_.bind(parts);
  parts.bind("records", records);
  parts.bind("split", split_list_);
  parts.bind("partials", partials_);
  parts.dispatch_indirect(GLintptr(offsetof(TileSplitList, part_groups_x)));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const Program& merge = merge_program(format, images);
  set_target_uniforms(merge, target);
  glProgramUniform1ui(merge.id(), merge.uniform("split_keys"), split_keys_);
  merge.use();
  tiles_.bind(merge);
  merge.bind("records", records);
  merge.bind("split", split_list_);
  merge.bind("partials", partials_);
  merge.bind("target", target_texture);
  merge.dispatch_indirect(GLintptr(offsetof(TileSplitList, merge_groups_x)));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

std::pair<uint32_t, uint32_t> GlSplatTileRaster::read_split_counts() const {
  if (!split_ran_) return {0, 0};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  TileSplitList list;
  split_list_.download(&list, sizeof(list));
  return {list.slots, list.slots == 0 ? 0 : std::min(list.parts, kTileSplatMaxParts)};
}

void GlSplatTileRaster::run_keys(const KeyPrograms& programs, KeyStep step, const Items& items, uint32_t gaussians,
                                 glm::ivec2 tile_grid) {
  const bool emit = step == KeyStep::kEmit;
  const Program& small = emit ? programs.emit : programs.count;
  const Program& huge = emit ? programs.huge_emit : programs.huge_count;
  if (emit)  // the counting passes need no slots
    for (const Program* p : {&small, &huge}) {
      if (!items.layers) glProgramUniform1ui(p->id(), p->uniform("gaussian_count"), gaussians);
      glProgramUniform2i(p->id(), p->uniform("tile_grid"), tile_grid.x, tile_grid.y);
      glProgramUniform1ui(p->id(), p->uniform("key_capacity"), tiles_.capacity());
    }
  glProgramUniform1ui(small.id(), small.uniform("item_capacity"), items.capacity);
  glProgramUniform1ui(small.id(), small.uniform("kept_word"), items.kept_word);
  // What both passes declare (key_bindings), by name; the planes' passes declare the layers.
  Buffer& counts = tiles_.counts(items.capacity);
  const auto bind_items = [&](const Program& p) {
    p.bind("records", *items.records);
    p.bind("entries", *items.entries);
    p.bind("tile_counts", counts);
    if (p.declares("kept")) p.bind("kept", *items.kept);
    if (p.declares("huge")) p.bind("huge", huge_);
    if (items.layers) p.bind("layers", *items.layers);
    tiles_.bind(p);  // writing: the keys and values
  };
  small.use();
  bind_items(small);
  small.dispatch_1d(items.capacity, int(kTileSplatItemsGroupSize));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (!emit)
    tiles_.write_dispatch(huge_, offsetof(TileHugeList, count) / 4, offsetof(TileHugeList, groups_x) / 4);
  huge.use();
  bind_items(huge);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, huge_.id());
  huge.dispatch_indirect(GLintptr(offsetof(TileHugeList, groups_x)));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GlSplatTileRaster::make_keys(const KeyPrograms& programs, const Items& items, uint32_t gaussians,
                             glm::ivec2 tile_grid, uint32_t slots, uint32_t pass) {
  huge_.ensure((std::max<size_t>(items.capacity, 1) + kTileHugeListWords) * 4);
  const TileHugeList no_huge{};
  huge_.upload(&no_huge, sizeof(no_huge));
  run_keys(programs, KeyStep::kCount, items, gaussians, tile_grid);
  tiles_.scan_to_capacity(items.capacity, capacity_.for_pass(items.capacity));
  run_keys(programs, KeyStep::kEmit, items, gaussians, tile_grid);
  tiles_.sort_and_find_ranges_to_capacity(slots);
  capacity_.record(tiles_, pass);
  // The tile sort rewrote the sorter's kept count: the key passes above read the items' count from
  // it (the depth sort's) before, nothing after.
}

std::vector<uint32_t> GlSplatTileRaster::overflowed_passes(uint32_t passes) {
  GlKeyCapacity::FrameKeys frame = capacity_.read_frame(passes);
  counts_.keys = uint32_t(std::min<uint64_t>(frame.sum, UINT32_MAX));
  return std::move(frame.overflowed);
}

size_t GlSplatTileRaster::pass_limit() const {
  if (pass_limit_ > 0) return pass_limit_;
  return device_pass_limit_;
}

uint32_t GlSplatTileRaster::read_huge_items() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  TileHugeList list;
  huge_.download(&list, sizeof(list));
  return list.count;
}

void GlSplatTileRaster::render_views(const GlScene& scene, std::span<const render::Camera> cameras,
                                const render::RasterSettings& settings, const TileViewsTarget& target,
                                const std::function<void(int)>& stamp) {
  if (!target.texture) throw std::invalid_argument("compute tile rasterizer: no target");
  passes_ = 0;
  if (cameras.empty()) return;
  const int W = cameras[0].width, H = cameras[0].height;
  for (const render::Camera& c : cameras)
    if (c.width != W || c.height != H) throw std::invalid_argument("compute tile rasterizer: views of different sizes");
  const size_t N = std::max<size_t>(scene.size(), 1);
  const size_t max_entries = std::min<size_t>(pass_limit() / sizeof(SplatRecord), (size_t(1) << 32) - 1);
  if (N > max_entries)
    throw_input_error("--raster compute: {} Gaussians need {:.0f} MiB of records a view, over the GPU's largest storage "
                      "buffer; use --raster hardware",
                      scene.size(), double(N * sizeof(SplatRecord)) / 1048576.0);
  const size_t views_per_pass = std::max<size_t>(1, max_entries / N);
  TileSplatCounts total{.entries = 0, .keys = 0, .slots = 0};
  const auto pass = [&](uint32_t p, const std::function<void(int)>& pass_stamp) {
    const size_t first = size_t(p) * views_per_pass;
    render_pass(scene, cameras.subspan(first, std::min(views_per_pass, cameras.size() - first)), uint32_t(first), p,
                settings, target, pass_stamp);
  };
  for (size_t first = 0; first < cameras.size(); first += views_per_pass) {
    pass(uint32_t(passes_), first == 0 ? stamp : std::function<void(int)>());
    total.entries += counts_.entries;
    total.slots += counts_.slots;
    ++passes_;
  }
  // The frame's one read: the passes' key totals; a pass whose keys did not fit is drawn again
  // with the capacity grown past them (the same keys then fit: once is enough).
  redrawn_ = 0;
  for (const uint32_t p : overflowed_passes(uint32_t(passes_))) {
    pass(p, {});
    ++redrawn_;
  }
  if (redrawn_ > 0) overflowed_passes(uint32_t(passes_));
  total.keys = counts_.keys;
  counts_ = total;
  if (stamp) stamp(3);
}

void GlSplatTileRaster::render_pass(const GlScene& scene, std::span<const render::Camera> cameras, uint32_t first_view,
                               uint32_t pass, const render::RasterSettings& settings, const TileViewsTarget& target,
                               const std::function<void(int)>& stamp) {
  const int W = cameras[0].width, H = cameras[0].height;
  const glm::ivec2 tile_grid{(W + render::kTileSize - 1) / render::kTileSize, (H + render::kTileSize - 1) / render::kTileSize};
  const uint32_t N = uint32_t(scene.size()), V = uint32_t(cameras.size());
  const size_t entries = size_t(N) * V;
  if (entries >= (size_t(1) << 32)) throw std::length_error("compute tile rasterizer: views x Gaussians over 2^32");
  const uint64_t slots = uint64_t(tile_grid.x) * tile_grid.y * V;
  if (slots >= (uint64_t(1) << 32)) throw std::length_error("compute tile rasterizer: views x tiles over 2^32");
  counts_ = {.entries = entries, .keys = 0, .slots = uint32_t(slots)};

  // Preprocess every (view, Gaussian).
  std::vector<TileViewCamera> view_cameras;
  for (const render::Camera& c : cameras) view_cameras.push_back(view_camera(c, settings));
  views_.ensure(view_cameras.size() * sizeof(TileViewCamera));
  views_.upload(view_cameras.data(), view_cameras.size() * sizeof(TileViewCamera));
  const size_t e = std::max<size_t>(entries, 1);
  records_.ensure(e * sizeof(SplatRecord));
  entry_keys_.ensure(e * 4);
  entries_.ensure(e * 4);
  if (N > 0) {
    const int requested = settings.sh_degree < 0 ? scene.sh_degree() : settings.sh_degree;
    const GLuint p = preprocess_.id();
    glProgramUniform1ui(p, preprocess_.uniform("gaussian_count"), N);
    glProgramUniform2i(p, preprocess_.uniform("image_size"), W, H);
    glProgramUniform2i(p, preprocess_.uniform("tile_grid"), tile_grid.x, tile_grid.y);
    glProgramUniform1f(p, preprocess_.uniform("dilation_px2"), settings.dilation_px2);
    glProgramUniform1f(p, preprocess_.uniform("scale_modifier"), settings.scale_modifier);
    glProgramUniform1i(p, preprocess_.uniform("sh_degree"), std::min(requested, scene.sh_degree()));
    glProgramUniform1i(p, preprocess_.uniform("sh_stride"), scene.sh_vec4_stride());
    preprocess_.use();
    preprocess_.bind("positions", scene.positions());
    preprocess_.bind("scales", scene.scales());
    preprocess_.bind("rotations", scene.rotations());
    preprocess_.bind("sh", scene.sh());
    preprocess_.bind("records", records_);
    preprocess_.bind("entry_keys", entry_keys_);
    preprocess_.bind("entries", entries_);
    preprocess_.bind("views", views_);
    // z: the view
    preprocess_.dispatch_groups((size_t(N) + kSplatPreprocessGroupSize - 1) / kSplatPreprocessGroupSize, V);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  if (stamp) stamp(1);

  // The items: every visible entry, front to back (the kept count stays on the GPU).
  SortKeys depth_order;
  depth_order.drop_culled = true;
  tiles_.sorter().sort(entry_keys_, entries_, uint32_t(entries), depth_order);
  Items items{.records = &records_, .entries = &entries_, .kept = &tiles_.sorter().kept_count_buffer(),
              .kept_word = offsetof(RadixSortParams, count) / 4, .layers = nullptr, .capacity = uint32_t(entries)};
  make_keys(view_keys_, items, N, tile_grid, uint32_t(slots), pass);
  if (stamp) stamp(2);

  // Every (view, tile): the empty ones write the background; the split ones get theirs after.
  const bool split = split_slots(capacity_.keys(), uint32_t(slots));
  const GLenum format = target.texture->internal_format();
  const Program& composite = composite_program(format, TileImages::kViews);
  const TargetUniforms where{.image_size = {W, H}, .tile_grid = tile_grid, .views = &target, .first_view = first_view};
  set_target_uniforms(composite, where);
  glProgramUniform1ui(composite.id(), composite.uniform("slot_count"), uint32_t(slots));
  composite.use();
  tiles_.bind(composite);
  composite.bind("records", records_);
  composite.bind("target", *target.texture);
  composite.dispatch_groups(slots);  // one group a slot
  if (split) composite_split(format, TileImages::kViews, where, records_, *target.texture);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("the compute tile rasterizer");
}

void GlSplatTileRaster::render_planes(const Buffer& records, const Buffer& sorted_ids, const Buffer& layers,
                                 const Buffer& draw, size_t gaussians, GlPlanes& planes,
                                 const std::function<void(int)>& stamp) {
  draw_planes(records, sorted_ids, layers, draw, gaussians, planes, stamp);
  // The one read (after the planes are composited): the key total; keys that did not fit are
  // drawn again with the capacity grown past them.
  redrawn_ = 0;
  if (overflowed_passes(1).empty()) return;
  draw_planes(records, sorted_ids, layers, draw, gaussians, planes, {});
  redrawn_ = 1;
  overflowed_passes(1);
}

void GlSplatTileRaster::draw_planes(const Buffer& records, const Buffer& sorted_ids, const Buffer& layers,
                               const Buffer& draw, size_t gaussians, GlPlanes& planes,
                               const std::function<void(int)>& stamp) {
  const glm::ivec2 tile_grid{(planes.width + render::kTileSize - 1) / render::kTileSize,
                             (planes.height + render::kTileSize - 1) / render::kTileSize};
  const uint64_t slots = uint64_t(tile_grid.x) * tile_grid.y * uint64_t(planes.max_planes);
  if (slots >= (uint64_t(1) << 32)) throw std::length_error("compute tile rasterizer: planes x tiles over 2^32");
  counts_ = {.entries = gaussians, .keys = 0, .slots = uint32_t(slots)};
  Items items{.records = &records, .entries = &sorted_ids, .kept = &draw,
              .kept_word = offsetof(DrawArraysIndirect, instance_count) / 4, .layers = &layers,
              .capacity = uint32_t(gaussians)};
  make_keys(plane_keys_, items, uint32_t(gaussians), tile_grid, uint32_t(slots), 0);
  if (stamp) stamp(1);

  const bool split = split_slots(capacity_.keys(), uint32_t(slots));
  const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glClearTexImage(planes.texels.id(), 0, GL_RGBA, GL_FLOAT, empty);
  const GLenum format = gl_internal_format(planes.format);
  const Program& composite = composite_program(format, TileImages::kPlanes);
  const TargetUniforms where{.image_size = {planes.width, planes.height}, .tile_grid = tile_grid};
  set_target_uniforms(composite, where);
  composite.use();
  tiles_.bind(composite);
  composite.bind("records", records);
  composite.bind("target", planes.texels);
  tiles_.dispatch_work(composite);
  if (split) composite_split(format, TileImages::kPlanes, where, records, planes.texels);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  if (stamp) stamp(2);
  check_gl("the compute tile rasterizer's planes");
}

size_t GlSplatTileRaster::plane_path_bytes(size_t items, size_t slots, size_t keys) {
  const size_t per_item = 4 + 4;                  // counts, huge list
  const size_t per_key = 4 * 4;                   // keys, values, the sort's two copies
  const size_t per_slot = 8 + 4;                  // ranges, work list
  const size_t split = kSplitListBytes + size_t(kTileSplatMaxParts) * kPartialBytes;  // at most
  return items * per_item + keys * per_key + slots * per_slot + split;
}

size_t GlSplatTileRaster::bytes() const {
  return tiles_.bytes() + views_.bytes() + records_.bytes() + entry_keys_.bytes() + entries_.bytes() + huge_.bytes() +
         split_list_.bytes() + partials_.bytes();
}

}  // namespace lfd::gpu
