#include "gpu/gl_radix_sort.hpp"

#include <algorithm>
#include <stdexcept>

#include "gpu/shaders/radix_histogram.comp.glsl.hpp"
#include "gpu/shaders/radix_scan.comp.glsl.hpp"
#include "gpu/shaders/radix_scatter.comp.glsl.hpp"

namespace lfd::gpu {
namespace {

constexpr uint32_t kTile = 256;           // elements ranked together (local_size_x)
constexpr uint32_t kTargetBlocks = 1024;  // enough work groups to fill a large GPU
constexpr uint32_t kMaxTilesPerBlock = 64;

void set_pass_uniforms(const Program& p, uint32_t count, uint32_t shift, uint32_t blocks, uint32_t items) {
  glProgramUniform1ui(p.id(), p.uniform("count"), count);
  glProgramUniform1ui(p.id(), p.uniform("shift"), shift);
  glProgramUniform1ui(p.id(), p.uniform("block_count"), blocks);
  glProgramUniform1ui(p.id(), p.uniform("block_items"), items);
}

}  // namespace

GlRadixSort::GlRadixSort()
    : histogram_("radix sort histogram", {{GL_COMPUTE_SHADER, radix_histogram_comp_glsl}}),
      scan_("radix sort scan", {{GL_COMPUTE_SHADER, radix_scan_comp_glsl}}),
      scatter_("radix sort scatter", {{GL_COMPUTE_SHADER, radix_scatter_comp_glsl}}),
      digit_totals_(256 * 4) {}

size_t GlRadixSort::scratch_bytes() const {
  return keys_tmp_.bytes() + values_tmp_.bytes() + block_offsets_.bytes() + digit_totals_.bytes();
}

void GlRadixSort::sort(Buffer& keys, Buffer& values, uint32_t count, int key_bits, int low_bit) {
  if (key_bits < 1 || key_bits > 32) throw std::invalid_argument("GlRadixSort: key_bits must be in 1..32");
  if (low_bit < 0 || low_bit >= key_bits) throw std::invalid_argument("GlRadixSort: low_bit must be in 0..key_bits - 1");
  if (size_t(count) * 4 > keys.bytes() || size_t(count) * 4 > values.bytes())
    throw std::invalid_argument("GlRadixSort: count exceeds the buffers");
  if (count <= 1) return;

  // Blocks of whole tiles, about kTargetBlocks of them (more for huge counts).
  const uint32_t tiles = (count + kTile - 1) / kTile;
  const uint32_t tiles_per_block = std::clamp<uint32_t>((tiles + kTargetBlocks - 1) / kTargetBlocks, 1, kMaxTilesPerBlock);
  const uint32_t block_items = tiles_per_block * kTile;
  const uint32_t blocks = (count + block_items - 1) / block_items;
  if (blocks > 65535) throw std::invalid_argument("GlRadixSort: too many keys for one dispatch");

  keys_tmp_.ensure(size_t(count) * 4);
  values_tmp_.ensure(size_t(count) * 4);
  block_offsets_.ensure(size_t(blocks) * 256 * 4);

  // Ping-pong: pass p reads copy p % 2 and writes the other.
  Buffer* key_copies[2] = {&keys, &keys_tmp_};
  Buffer* value_copies[2] = {&values, &values_tmp_};
  const int passes = (key_bits - low_bit + 7) / 8;
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  for (int pass = 0; pass < passes; ++pass) {
    const uint32_t shift = uint32_t(low_bit + 8 * pass);
    set_pass_uniforms(histogram_, count, shift, blocks, block_items);
    set_pass_uniforms(scatter_, count, shift, blocks, block_items);
    glProgramUniform1ui(scan_.id(), scan_.uniform("block_count"), blocks);

    key_copies[pass % 2]->bind_storage(0);
    block_offsets_.bind_storage(1);
    digit_totals_.bind_storage(2);
    value_copies[pass % 2]->bind_storage(3);
    key_copies[(pass + 1) % 2]->bind_storage(4);
    value_copies[(pass + 1) % 2]->bind_storage(5);

    histogram_.use();
    glDispatchCompute(blocks, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scan_.use();
    glDispatchCompute(256, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scatter_.use();
    glDispatchCompute(blocks, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  if (passes % 2 == 1) {  // the result is in the scratch copies
    glCopyNamedBufferSubData(keys_tmp_.id(), keys.id(), 0, 0, GLsizeiptr(count) * 4);
    glCopyNamedBufferSubData(values_tmp_.id(), values.id(), 0, 0, GLsizeiptr(count) * 4);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("the radix sort");
}

}  // namespace lfd::gpu
