#include "gpu/compute/gl_radix_sort.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "gpu/compute/shaders/radix_histogram.comp.glsl.hpp"
#include "gpu/compute/shaders/radix_scan.comp.glsl.hpp"
#include "gpu/compute/shaders/radix_scatter.comp.glsl.hpp"
#include "gpu/compute/shaders/radix_setup.comp.glsl.hpp"
#include "gpu/compute/shaders/radix_sort_io.h"
#include "gpu/gl/shaders/work_groups_io.h"

namespace lfd::gpu {
namespace {

static_assert(kRadixTile == kRadixDigits, "the histogram and the scatter count one digit per invocation");
static_assert(sizeof(RadixSortParams) == 8 * sizeof(uint32_t) && offsetof(RadixSortParams, groups_x) == 16,
              "RadixSortParams is std430: packed uints");

Program pass_program(const char* label, const char* source) { return Program(label, {{GL_COMPUTE_SHADER, source}}); }

struct BlockLayout {
  uint32_t items = 0, blocks = 0;
};

// Blocks of whole tiles, about kRadixTargetBlocks of them (more for huge counts); radix_setup makes
// the same choice on the GPU.
BlockLayout block_layout(uint32_t count) {
  const uint32_t tiles = (count + kRadixTile - 1) / kRadixTile;
  const uint32_t tiles_per_block = std::clamp<uint32_t>((tiles + kRadixTargetBlocks - 1) / kRadixTargetBlocks, 1, kRadixMaxTilesPerBlock);
  BlockLayout layout;
  layout.items = tiles_per_block * kRadixTile;
  layout.blocks = std::max<uint32_t>(1, (count + layout.items - 1) / layout.items);
  return layout;
}

// What a pass reads: the scan only the block count (the length of its rows of block counts); the
// histogram and the scatter the keys too. A program gets only the uniforms it reads (the scan's
// compiler drops the others, which strict GL checks refuse to set).
enum class PassReads { kBlockCount, kKeys };

// The uniforms of one pass, and those last set on a program: only what changed is set again
// (a sort of 3 passes would otherwise make 60 uniform calls a view; docs/gpu.md "A frame that
// never waits" counts the calls).
void set_changed(const Program& p, PassReads reads, RadixPassUniforms& last, const RadixPassUniforms& now) {
  const auto set = [&](const char* name, uint32_t RadixPassUniforms::*field) {
    if (last.*field == now.*field) return;
    glProgramUniform1ui(p.id(), p.uniform(name), now.*field);
  };
  set("block_count", &RadixPassUniforms::block_count);
  set("later_pass", &RadixPassUniforms::later);
  if (reads == PassReads::kKeys) {
    set("count", &RadixPassUniforms::count);
    set("block_items", &RadixPassUniforms::block_items);
    set("drop_culled", &RadixPassUniforms::drop);
    set("normalise_bits", &RadixPassUniforms::normalise_bits);
    set("shift", &RadixPassUniforms::shift);
  }
  last = now;
}

void check_keys(const SortKeys& how) {
  if (how.normalise_bits != 0) {
    if (how.normalise_bits % 8 != 0 || how.normalise_bits < 8 || how.normalise_bits > 24)
      throw std::invalid_argument("GlRadixSort: normalise_bits must be 8, 16 or 24");
    if (!how.drop_culled || how.key_range == nullptr)
      throw std::invalid_argument("GlRadixSort: normalised keys need drop_culled and a key range");
    return;
  }
  if (how.key_bits < 1 || how.key_bits > 32) throw std::invalid_argument("GlRadixSort: key_bits must be in 1..32");
  if (how.low_bit < 0 || how.low_bit >= how.key_bits)
    throw std::invalid_argument("GlRadixSort: low_bit must be in 0..key_bits - 1");
}

}  // namespace

GlRadixSort::GlRadixSort()
    : histogram_(pass_program("radix sort histogram", radix_histogram_comp_glsl)),
      scan_(pass_program("radix sort scan", radix_scan_comp_glsl)),
      scatter_(pass_program("radix sort scatter", radix_scatter_comp_glsl)),
      setup_(pass_program("radix sort setup", radix_setup_comp_glsl)),
      digit_totals_(kRadixDigits * sizeof(uint32_t)),
      params_(sizeof(RadixSortParams)) {}

size_t GlRadixSort::scratch_bytes() const {
  return keys_tmp_.bytes() + values_tmp_.bytes() + block_offsets_.bytes() + digit_totals_.bytes() + params_.bytes();
}

int GlRadixSort::passes(const SortKeys& how) {
  if (how.normalise_bits != 0) return (how.normalise_bits + 7) / 8;
  return (how.key_bits - how.low_bit + 7) / 8;
}

void GlRadixSort::sort(Buffer& keys, Buffer& values, uint32_t count, const SortKeys& how) {
  check_keys(how);
  if (size_t(count) * 4 > keys.bytes() || size_t(count) * 4 > values.bytes())
    throw std::invalid_argument("GlRadixSort: count exceeds the buffers");
  // Without dropping, 0 or 1 keys are sorted; with it a single key may still be dropped.
  if (count == 0 && how.drop_culled) {  // nothing kept: what kept_count_buffer() promises
    const RadixSortParams none;
    params_.upload(&none, sizeof(none));
  }
  if (count == 0 || (count == 1 && !how.drop_culled)) return;

  const BlockLayout first = block_layout(count);
  // The passes index blocks by gl_WorkGroupID.x alone (the later ones are dispatched indirectly
  // from radix_setup's one row).
  if (first.blocks > kMaxWorkGroupsX) throw std::invalid_argument("GlRadixSort: too many keys for one dispatch");
  keys_tmp_.ensure(size_t(count) * 4);
  values_tmp_.ensure(size_t(count) * 4);
  // The later passes' layout (for at most `count` kept keys) has at most max(first, kRadixTargetBlocks) blocks.
  block_offsets_.ensure(size_t(std::max(first.blocks, kRadixTargetBlocks)) * kRadixDigits * sizeof(uint32_t));

  // Ping-pong: pass p reads copy p % 2 and writes the other.
  Buffer* key_copies[2] = {&keys, &keys_tmp_};
  Buffer* value_copies[2] = {&values, &values_tmp_};
  const int passes = GlRadixSort::passes(how);
  const int low_bit = how.normalise_bits ? 0 : how.low_bit;
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  params_.bind_storage(kRadixParamsBinding);
  if (how.key_range) how.key_range->bind_storage(kRadixKeyRangeBinding);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, params_.id());
  for (int pass = 0; pass < passes; ++pass) {
    const uint32_t shift = uint32_t(low_bit + 8 * pass);
    const bool later = how.drop_culled && pass > 0;
    const bool drop = how.drop_culled && pass == 0;
    const uint32_t normalise = pass == 0 ? uint32_t(how.normalise_bits) : 0u;
    const RadixPassUniforms now{count, first.blocks, first.items, later, drop, normalise, shift};
    set_changed(histogram_, PassReads::kKeys, last_uniforms_[0], now);
    set_changed(scan_, PassReads::kBlockCount, last_uniforms_[1], now);
    set_changed(scatter_, PassReads::kKeys, last_uniforms_[2], now);

    key_copies[pass % 2]->bind_storage(kRadixKeysInBinding);
    block_offsets_.bind_storage(kRadixBlockCountsBinding);
    digit_totals_.bind_storage(kRadixDigitTotalsBinding);
    value_copies[pass % 2]->bind_storage(kRadixValuesInBinding);
    key_copies[(pass + 1) % 2]->bind_storage(kRadixKeysOutBinding);
    value_copies[(pass + 1) % 2]->bind_storage(kRadixValuesOutBinding);

    const auto dispatch_blocks = [&] {
      if (later) glDispatchComputeIndirect(GLintptr(offsetof(RadixSortParams, groups_x)));
      else glDispatchCompute(first.blocks, 1, 1);
    };
    histogram_.use();
    dispatch_blocks();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scan_.use();
    glDispatchCompute(kRadixDigits, 1, 1);  // a work group per digit
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scatter_.use();
    dispatch_blocks();
    if (drop) {  // the kept count and the later passes' layout, from this pass's digit totals
      setup_.use();
      glDispatchCompute(1, 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    } else {
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
  }
  if (passes % 2 == 1) {  // the result is in the scratch copies
    glCopyNamedBufferSubData(keys_tmp_.id(), keys.id(), 0, 0, GLsizeiptr(count) * 4);
    glCopyNamedBufferSubData(values_tmp_.id(), values.id(), 0, 0, GLsizeiptr(count) * 4);
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("the radix sort");
}

}  // namespace lfd::gpu
