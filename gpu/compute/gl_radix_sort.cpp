#include "gpu/compute/gl_radix_sort.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

// What each pass reads and writes (docs/gpu.md "Binding points"). Every pass declares the params
// (its layout on a sort's later passes) and the keys' range (the first pass of normalised keys):
// radix_common.glsl declares both, and the linker keeps a declared std430 block active even in a
// pass that does not read it (the scan, the setup).
Binding params(Access access) { return storage_buffer("params", kRadixParamsBinding, access); }
Binding key_range() { return storage_buffer("key_range", kRadixKeyRangeBinding, Access::read); }

Program pass_program(const char* label, const char* source, std::vector<Binding> bindings) {
  return Program(label, {{GL_COMPUTE_SHADER, source}}, {}, std::move(bindings));
}

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
    : histogram_(pass_program("radix sort histogram", radix_histogram_comp_glsl,
                              {storage_buffer("keys_in", kRadixKeysInBinding, Access::read),
                               storage_buffer("block_counts", kRadixBlockCountsBinding, Access::write),
                               params(Access::read), key_range()})),
      scan_(pass_program("radix sort scan", radix_scan_comp_glsl,
                         {storage_buffer("block_counts", kRadixBlockCountsBinding, Access::read_write),
                          storage_buffer("digit_totals", kRadixDigitTotalsBinding, Access::write),
                          params(Access::read), key_range()})),
      scatter_(pass_program("radix sort scatter", radix_scatter_comp_glsl,
                            {storage_buffer("keys_in", kRadixKeysInBinding, Access::read),
                             storage_buffer("block_counts", kRadixBlockCountsBinding, Access::read),
                             storage_buffer("digit_totals", kRadixDigitTotalsBinding, Access::read),
                             storage_buffer("values_in", kRadixValuesInBinding, Access::read),
                             storage_buffer("keys_out", kRadixKeysOutBinding, Access::write),
                             storage_buffer("values_out", kRadixValuesOutBinding, Access::write),
                             params(Access::read), key_range()})),
      setup_(pass_program("radix sort setup", radix_setup_comp_glsl,
                          {storage_buffer("digit_totals", kRadixDigitTotalsBinding, Access::read),
                           params(Access::read_write), key_range()})),
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
  // A sort without normalised keys never reads the range; the point still holds a buffer of the
  // sort's (the params), so the check before each dispatch sees what the pass bound.
  const Buffer& range = how.key_range ? *how.key_range : params_;
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

    const Buffer& keys_in = *key_copies[pass % 2];
    const Buffer& values_in = *value_copies[pass % 2];
    const Buffer& keys_out = *key_copies[(pass + 1) % 2];
    const Buffer& values_out = *value_copies[(pass + 1) % 2];
    const auto dispatch_blocks = [&](const Program& p) {
      if (later) p.dispatch_indirect(GLintptr(offsetof(RadixSortParams, groups_x)));
      else p.dispatch(first.blocks, 1, 1);
    };
    // Each pass binds by name all it declares, though most points already hold the same buffer:
    // the check before its dispatch compares against what this pass bound (docs/gpu.md "Binding
    // points"), and a glBindBufferBase costs no round trip.
    histogram_.use();
    histogram_.bind("keys_in", keys_in);
    histogram_.bind("block_counts", block_offsets_);
    histogram_.bind("params", params_);
    histogram_.bind("key_range", range);
    dispatch_blocks(histogram_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scan_.use();
    scan_.bind("block_counts", block_offsets_);
    scan_.bind("digit_totals", digit_totals_);
    scan_.bind("params", params_);
    scan_.bind("key_range", range);
    scan_.dispatch(kRadixDigits, 1, 1);  // a work group per digit
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scatter_.use();
    scatter_.bind("keys_in", keys_in);
    scatter_.bind("block_counts", block_offsets_);
    scatter_.bind("digit_totals", digit_totals_);
    scatter_.bind("values_in", values_in);
    scatter_.bind("keys_out", keys_out);
    scatter_.bind("values_out", values_out);
    scatter_.bind("params", params_);
    scatter_.bind("key_range", range);
    dispatch_blocks(scatter_);
    if (drop) {  // the kept count and the later passes' layout, from this pass's digit totals
      setup_.use();
      setup_.bind("digit_totals", digit_totals_);
      setup_.bind("params", params_);
      setup_.bind("key_range", range);
      setup_.dispatch(1, 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    } else {
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
  }
  if (passes % 2 == 1) {  // the result is in the scratch copies
    // The copy reads what the scatter wrote only after this barrier (GL 4.5 7.12.2: buffer
    // updates are not ordered after shader writes without it; docs/gpu.md "Drivers and limits").
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glCopyNamedBufferSubData(keys_tmp_.id(), keys.id(), 0, 0, GLsizeiptr(count) * 4);
    glCopyNamedBufferSubData(values_tmp_.id(), values.id(), 0, 0, GLsizeiptr(count) * 4);
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("the radix sort");
}

}  // namespace lfd::gpu
