#pragma once
// Pass 2 of the GL per-view renderer: a stable key-value LSD radix sort of 32-bit keys with
// 32-bit values in compute shaders (gpu/shaders/radix_*.comp.glsl), 8 bits per pass, that needs
// no subgroup extensions (Mesa llvmpipe has none). Per pass:
//   histogram  each block of elements counts its digits in shared memory
//   scan       per digit, the exclusive prefix over the blocks (digit-major table), and the
//              digit totals
//   scatter    each block ranks its elements among equal digits in 256-element tiles (a shared
//              bit mask per digit, popcounts of the lower threads' bits: a stable rank without
//              subgroup ballots) and writes them to base(digit) + offset(digit, block) + rank.
// Stable, so equal keys keep their input order (the reference's depth ties keep the Gaussian
// order). Correct for any count, including 0 and 1.
#include <cstdint>

#include "gpu/gl_objects.hpp"

namespace lfd::gpu {

class GlRadixSort {
 public:
  GlRadixSort();  // needs a current context; compiles the three passes

  // Sorts the first `count` keys (and the values with them) ascending, in place, on the GPU,
  // by bits low_bit .. key_bits - 1 (key_bits in 1..32, low_bit in 0..key_bits - 1; one pass per
  // 8 bits from low_bit; bits above are ignored, and keys equal in the sorted bits keep their
  // order: sorting by key >> low_bit).
  // Issues the barriers its consumers need (storage, indirect command, downloads).
  void sort(Buffer& keys, Buffer& values, uint32_t count, int key_bits = 32, int low_bit = 0);

  size_t scratch_bytes() const;

 private:
  Program histogram_, scan_, scatter_;
  Buffer keys_tmp_, values_tmp_, block_offsets_, digit_totals_;
};

}  // namespace lfd::gpu
