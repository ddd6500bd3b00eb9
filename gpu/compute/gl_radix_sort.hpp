#pragma once
// Pass 2 of the GL per-view renderer and G2LF's binning sort: a stable key-value LSD radix sort
// of 32-bit keys with 32-bit values in compute shaders (gpu/compute/shaders/radix_*.comp.glsl), 8 bits
// per pass, that needs no subgroup extensions (Mesa llvmpipe has no GL_KHR_shader_subgroup).
// Per pass:
//   histogram  each block of elements counts its digits in shared memory
//   scan       per digit, the exclusive prefix over the blocks (digit-major table), and the
//              digit totals
//   scatter    each block ranks its elements among equal digits in 256-element tiles (a shared
//              bit mask per digit, popcounts of the lower threads' bits: a stable rank without
//              subgroup ballots) and writes them to base(digit) + offset(digit, block) + rank.
// Stable, so equal keys keep their input order (the reference's depth ties keep the Gaussian
// order). Correct for any count, including 0 and 1.
//
// Sorting what is visible (SortKeys::drop_culled; docs/gpu.md "Sorting what is visible"): the
// first pass drops the culled keys (0xFFFFFFFF) as it scatters, stably, so the kept keys leave
// it compacted in their input order; a one-group setup pass sums its digit totals into the kept
// count and writes the later passes' block layout and work-group count to a buffer they are
// dispatched from (glDispatchComputeIndirect). The later passes run over the kept keys only and
// nothing is read back. Normalised keys (SortKeys::normalise_bits): the first pass replaces a
// key (a positive depth's float bits) by (key - min) >> s over the kept keys' range [min, max]
// (a buffer the caller filled on the GPU), s the smallest shift that fits max - min in the bits:
// the float bits are a piecewise-linear log2 of the depth, so 16 bits spread over the visible
// depths order them to a relative 2^(s - 23) and fill the digits evenly, where the raw bits'
// top digit holds nearly every key (one hot bucket).
#include <array>
#include <cstdint>

#include "gpu/gl/gl_objects.hpp"

namespace lfd::gpu {

struct SortKeys {
  // Bits low_bit .. key_bits - 1 are sorted (key_bits in 1..32, low_bit in 0..key_bits - 1; one
  // pass per 8 bits from low_bit; bits above are ignored, and keys equal in the sorted bits keep
  // their order: sorting by key >> low_bit). With normalise_bits: the normalised keys' bits.
  int key_bits = 32;
  int low_bit = 0;
  // Drop keys 0xFFFFFFFF in the first pass; the kept ones end first, sorted, and the positions
  // after them hold stale data. The kept count stays on the GPU (kept_count_buffer()).
  bool drop_culled = false;
  // > 0 (8, 16, 24): sort keys normalised to the kept keys' range in this many bits (needs
  // drop_culled and key_range: two uints, the kept keys' smallest and largest). key_bits and
  // low_bit are then ignored.
  int normalise_bits = 0;
  const Buffer* key_range = nullptr;
};

// The uniforms of one sort pass (what GlRadixSort set last on each program; it sets only what
// changes).
struct RadixPassUniforms {
  uint32_t count = 0, block_count = 0, block_items = 0, later = 0, drop = 0, normalise_bits = 0, shift = 0;
};

class GlRadixSort {
 public:
  GlRadixSort();  // needs a current context; compiles the passes

  // Sorts the first `count` keys (and the values with them) ascending, in place, on the GPU.
  // Issues the barriers its consumers need (storage, indirect command, downloads).
  void sort(Buffer& keys, Buffer& values, uint32_t count, const SortKeys& how);
  void sort(Buffer& keys, Buffer& values, uint32_t count, int key_bits = 32, int low_bit = 0) {
    sort(keys, values, count, SortKeys{key_bits, low_bit});
  }

  // After a sort with drop_culled: the kept count is its first uint (written on the GPU).
  const Buffer& kept_count_buffer() const { return params_; }
  // Passes (each: histogram, scan, scatter dispatches and their barriers) of a sort.
  static int passes(const SortKeys& how);

  size_t scratch_bytes() const;

 private:
  Program histogram_, scan_, scatter_, setup_;
  Buffer keys_tmp_, values_tmp_, block_offsets_, digit_totals_, params_;
  std::array<RadixPassUniforms, 3> last_uniforms_{};  // histogram, scan, scatter (GL sets 0 at link)
};

}  // namespace lfd::gpu
