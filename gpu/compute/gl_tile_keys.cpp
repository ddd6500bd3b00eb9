#include "gpu/compute/gl_tile_keys.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "gpu/gl/gl_work_groups.hpp"
#include "gpu/compute/shaders/tile_dispatch.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_ranges.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_scan_blocks.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_scan_items.comp.glsl.hpp"
#include "gpu/compute/shaders/tile_scan_totals.comp.glsl.hpp"

namespace lfd::gpu {
namespace {

static_assert(kTileScanBlockItems == kTileScanGroupSize * kTileScanPerInvocation);
static_assert(sizeof(TileState) == 32 && offsetof(TileState, groups_x) == 16, "TileState is std430: packed uints");

Program compute(const char* label, const char* source) { return Program(label, {{GL_COMPUTE_SHADER, source}}); }

}  // namespace

std::vector<std::string> key_pass_defines(KeyStep step, TileImages images) {
  return {std::string("EMIT ") + (step == KeyStep::kEmit ? "1" : "0"),
          std::string("PLANES ") + (images == TileImages::kPlanes ? "1" : "0")};
}

int slot_bits(uint32_t slots) {
  int bits = 1;
  while (bits < 32 && (uint64_t(1) << bits) < slots) ++bits;
  return bits;
}

GlTileKeys::GlTileKeys()
    : blocks_(compute("tiles: scan blocks", tile_scan_blocks_comp_glsl)),
      totals_(compute("tiles: scan totals", tile_scan_totals_comp_glsl)),
      items_(compute("tiles: scan items", tile_scan_items_comp_glsl)),
      ranges_(compute("tiles: ranges", tile_ranges_comp_glsl)),
      dispatch_(compute("tiles: indirect dispatch", tile_dispatch_comp_glsl)) {
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
  counts_.bind_storage(kTileCountsBinding);
  block_sums_.bind_storage(kTileBlockSumsBinding);
  state_.bind_storage(kTileStateBinding);
  glProgramUniform1ui(blocks_.id(), blocks_.uniform("item_count"), items);
  glProgramUniform1ui(items_.id(), items_.uniform("item_count"), items);
  glProgramUniform1ui(totals_.id(), totals_.uniform("block_count"), blocks);
  blocks_.use();
  dispatch_work_groups(blocks);  // a group a block
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  totals_.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  items_.use();
  dispatch_work_groups(blocks);
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
    keys_.bind_storage(kTileKeysBinding);
    ranges_buffer_.bind_storage(kTileRangesBinding);
    work_.bind_storage(kTileWorkBinding);
    state_.bind_storage(kTileStateBinding);
    glProgramUniform1ui(ranges_.id(), ranges_.uniform("key_count"), keys);
    glProgramUniform1i(ranges_.id(), ranges_.uniform("count_from_state"), count_from_state ? 1 : 0);
    ranges_.use();
    dispatch_work_groups((size_t(keys) + kTileRangesGroupSize - 1) / kTileRangesGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  write_dispatch(state_, offsetof(TileState, work_count) / 4, offsetof(TileState, groups_x) / 4);
  check_gl("the tile ranges");
}

void GlTileKeys::write_dispatch(const Buffer& buffer, uint32_t count_word, uint32_t dispatch_word) const {
  buffer.bind_storage(kTileStateBinding);
  glProgramUniform1ui(dispatch_.id(), dispatch_.uniform("count_word"), count_word);
  glProgramUniform1ui(dispatch_.id(), dispatch_.uniform("dispatch_word"), dispatch_word);
  dispatch_.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void GlTileKeys::bind() const {
  keys_.bind_storage(kTileKeysBinding);
  values_.bind_storage(kTileValuesBinding);
  ranges_buffer_.bind_storage(kTileRangesBinding);
  work_.bind_storage(kTileWorkBinding);
  state_.bind_storage(kTileStateBinding);
}

void GlTileKeys::dispatch_work() const {
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, state_.id());
  glDispatchComputeIndirect(GLintptr(offsetof(TileState, groups_x)));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

size_t GlTileKeys::bytes() const {
  return counts_.bytes() + block_sums_.bytes() + state_.bytes() + keys_.bytes() + values_.bytes() +
         ranges_buffer_.bytes() + work_.bytes() + sort_.scratch_bytes();
}

}  // namespace lfd::gpu
