#include "gpu/compute/gl_tile_keys.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gpu/compute/shaders/tile_dispatch.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_ranges.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_scan_blocks.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_scan_items.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_scan_totals.comp.glsl.hpp"

namespace lfd::gpu {
namespace {

static_assert(kTileScanBlockItems == kTileScanGroupSize * kTileScanPerInvocation);
static_assert(sizeof(TileState) == 32 && offsetof(TileState, groups_x) == 16, "TileState is std430: packed uints");

Program compute(const char* label, const char* source, std::vector<Binding> bindings) {
  return Program(label, {{GL_COMPUTE_SHADER, source}}, {}, std::move(bindings));
}

Binding block_sums(Access access) { return storage_buffer("block_sums", kTileBlockSumsBinding, access); }

}  // namespace

std::vector<std::string> key_pass_defines(KeyStep step, TileImages images) {
  return {std::string("EMIT ") + (step == KeyStep::kEmit ? "1" : "0"),
          std::string("PLANES ") + (images == TileImages::kPlanes ? "1" : "0")};
}

Binding tile_counts(Access access) { return storage_buffer("tile_counts", kTileCountsBinding, access); }
Binding tile_keys(Access access) { return storage_buffer("tile_keys", kTileKeysBinding, access); }
Binding tile_values(Access access) { return storage_buffer("tile_values", kTileValuesBinding, access); }
Binding tile_ranges(Access access) { return storage_buffer("tile_ranges", kTileRangesBinding, access); }
Binding tile_work(Access access) { return storage_buffer("tile_work", kTileWorkBinding, access); }
Binding tile_state(Access access) { return storage_buffer("tile_state", kTileStateBinding, access); }

int slot_bits(uint32_t slots) {
  int bits = 1;
  while (bits < 32 && (uint64_t(1) << bits) < slots) ++bits;
  return bits;
}

GlTileKeys::GlTileKeys()
    : blocks_(compute("tiles: scan blocks", tile_scan_blocks_comp_glsl,
                      {tile_counts(Access::read), block_sums(Access::write)})),
      totals_(compute("tiles: scan totals", tile_scan_totals_comp_glsl,
                      {block_sums(Access::read_write), tile_state(Access::read_write)})),
      items_(compute("tiles: scan items", tile_scan_items_comp_glsl,
                     {tile_counts(Access::read_write), block_sums(Access::read)})),
      ranges_(compute("tiles: ranges", tile_ranges_comp_glsl,
                      {tile_keys(Access::read), tile_ranges(Access::write), tile_work(Access::write),
                       tile_state(Access::read_write)})),
      // A client's list too (write_dispatch): its words at the state's point.
      dispatch_(compute("tiles: indirect dispatch", tile_dispatch_comp_glsl,
                        {storage_buffer("target", kTileStateBinding, Access::read_write)})) {
  state_.ensure(sizeof(TileState));
}

Buffer& GlTileKeys::counts(size_t items) {
  counts_.ensure(std::max<size_t>(items, 1) * 4);
  return counts_;
}

bool GlTileKeys::run_scan(uint32_t items) {
  const TileState reset{};
  state_.upload(&reset, sizeof(reset));
  if (items == 0) return false;
  const uint32_t blocks = (items + kTileScanBlockItems - 1) / kTileScanBlockItems;
  if (blocks > kTileScanMaxBlocks) throw std::length_error("tile keys: more items than one scan covers (2^30)");
  block_sums_.ensure(size_t(blocks) * 4);
  glProgramUniform1ui(blocks_.id(), blocks_.uniform("item_count"), items);
  glProgramUniform1ui(items_.id(), items_.uniform("item_count"), items);
  glProgramUniform1ui(totals_.id(), totals_.uniform("block_count"), blocks);
  blocks_.use();
  blocks_.bind("tile_counts", counts_);
  blocks_.bind("block_sums", block_sums_);
  blocks_.dispatch_groups(blocks);  // a group a block
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  totals_.use();
  totals_.bind("block_sums", block_sums_);
  totals_.bind("tile_state", state_);
  totals_.dispatch(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  items_.use();
  items_.bind("tile_counts", counts_);
  items_.bind("block_sums", block_sums_);
  items_.dispatch_groups(blocks);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("the tile scan");
  return true;
}

uint32_t GlTileKeys::scan(uint32_t items) {
  if (!run_scan(items)) return 0;
  uint32_t total = 0;
  state_.download(&total, sizeof(total));
  keys_.ensure(std::max<size_t>(total, 1) * 4);
  values_.ensure(std::max<size_t>(total, 1) * 4);
  return total;
}

void GlTileKeys::scan_to_capacity(uint32_t items, uint32_t capacity) {
  capacity_ = capacity;
  keys_.ensure(std::max<size_t>(capacity, 1) * 4);
  values_.ensure(std::max<size_t>(capacity, 1) * 4);
  const uint32_t no_key = 0xFFFFFFFFu;
  if (capacity > 0)
    glClearNamedBufferSubData(keys_.id(), GL_R32UI, 0, GLsizeiptr(capacity) * 4, GL_RED_INTEGER, GL_UNSIGNED_INT,
                              &no_key);
  run_scan(items);
}

void GlTileKeys::copy_key_total(const Buffer& buffer, uint32_t word) const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glCopyNamedBufferSubData(state_.id(), buffer.id(), GLintptr(offsetof(TileState, keys)), GLintptr(word) * 4, 4);
}

void GlTileKeys::sort_and_find_ranges(uint32_t keys, uint32_t slots) {
  const TileState reset{.keys = keys};
  state_.upload(&reset, sizeof(reset));
  sort_.sort(keys_, values_, keys, slot_bits(slots));
  find_ranges(keys, slots, false);
}

void GlTileKeys::sort_and_find_ranges_to_capacity(uint32_t slots) {
  const uint32_t no_work = 0;
  state_.upload(&no_work, 4, offsetof(TileState, work_count));
  SortKeys by_slot;
  by_slot.key_bits = slot_bits(slots);
  by_slot.drop_culled = true;  // the keys not written (0xFFFFFFFF)
  sort_.sort(keys_, values_, capacity_, by_slot);
  find_ranges(capacity_, slots, true);
}

void GlTileKeys::find_ranges(uint32_t keys, uint32_t slots, bool count_from_state) {
  ranges_buffer_.ensure(std::max<size_t>(slots, 1) * 8);
  work_.ensure(std::max<size_t>(slots, 1) * 4);
  glClearNamedBufferData(ranges_buffer_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  if (keys > 0) {
    glProgramUniform1ui(ranges_.id(), ranges_.uniform("key_count"), keys);
    glProgramUniform1i(ranges_.id(), ranges_.uniform("count_from_state"), count_from_state ? 1 : 0);
    ranges_.use();
    bind(ranges_);
    ranges_.dispatch_groups((size_t(keys) + kTileRangesGroupSize - 1) / kTileRangesGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  write_dispatch(state_, offsetof(TileState, work_count) / 4, offsetof(TileState, groups_x) / 4);
  check_gl("the tile ranges");
}

void GlTileKeys::write_dispatch(const Buffer& buffer, uint32_t count_word, uint32_t dispatch_word) const {
  glProgramUniform1ui(dispatch_.id(), dispatch_.uniform("count_word"), count_word);
  glProgramUniform1ui(dispatch_.id(), dispatch_.uniform("dispatch_word"), dispatch_word);
  dispatch_.use();
  dispatch_.bind("target", buffer);
  dispatch_.dispatch(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void GlTileKeys::bind(const Program& program) const {
  const std::pair<Binding, const Buffer*> buffers[] = {{tile_keys(Access::read), &keys_},
                                                       {tile_values(Access::read), &values_},
                                                       {tile_ranges(Access::read), &ranges_buffer_},
                                                       {tile_work(Access::read), &work_},
                                                       {tile_state(Access::read), &state_}};
  for (const auto& [binding, buffer] : buffers)
    if (program.declares(binding.name)) program.bind(binding.name, *buffer);
}

void GlTileKeys::dispatch_work(const Program& program) const {
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, state_.id());
  program.dispatch_indirect(GLintptr(offsetof(TileState, groups_x)));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

size_t GlTileKeys::bytes() const {
  return counts_.bytes() + block_sums_.bytes() + state_.bytes() + keys_.bytes() + values_.bytes() +
         ranges_buffer_.bytes() + work_.bytes() + sort_.scratch_bytes();
}

}  // namespace lfd::gpu
