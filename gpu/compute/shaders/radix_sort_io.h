// The radix sort's contract (gpu/compute/gl_radix_sort.hpp; gpu/compute/shaders/radix_*.comp.glsl): its storage
// buffers' binding points, its digit and tile sizes, the block layout rule's limits (which
// GlRadixSort::sort applies on the CPU and radix_setup on the GPU) and SortParams, the buffer the
// later passes read their layout from and are dispatched from. Read by C++ and GLSL
// (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_RADIX_SORT_IO_H
#define LFD_GPU_SHADERS_RADIX_SORT_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

// Storage buffers. A pass reads copy p % 2 of the keys and values and writes the other.
LFD_IO_INT(kRadixKeysInBinding, 0)
LFD_IO_INT(kRadixBlockCountsBinding, 1)  // [digit * blocks + block]: counts, then offsets
LFD_IO_INT(kRadixDigitTotalsBinding, 2)  // kRadixDigits
LFD_IO_INT(kRadixValuesInBinding, 3)
LFD_IO_INT(kRadixKeysOutBinding, 4)
LFD_IO_INT(kRadixValuesOutBinding, 5)
LFD_IO_INT(kRadixParamsBinding, 6)    // RadixSortParams
LFD_IO_INT(kRadixKeyRangeBinding, 7)  // the kept keys' smallest and largest value (normalised keys)

// 8-bit digits: the scan runs one work group per digit. A tile is the elements one work group
// ranks together, one per invocation: every pass's local_size_x. The histogram and the scatter
// keep one counter per digit in one invocation each, so the two are equal (gl_radix_sort.cpp
// asserts it).
LFD_IO_UINT(kRadixDigits, 256u)
LFD_IO_UINT(kRadixTile, 256u)
// A block is whole tiles, about kRadixTargetBlocks of them (enough work groups to fill a large
// GPU), at most kRadixMaxTilesPerBlock tiles each (more blocks for huge counts).
LFD_IO_UINT(kRadixTargetBlocks, 1024u)
LFD_IO_UINT(kRadixMaxTilesPerBlock, 64u)

// After the first pass of a sort that drops culled keys, radix_setup writes the kept count, its
// block layout and the later passes' DispatchIndirectCommand here (std430: tightly packed uints).
struct RadixSortParams {
  uint count LFD_IO_ZERO;
  uint block_count LFD_IO_ZERO;
  uint block_items LFD_IO_ZERO;  // a multiple of kRadixTile
  uint pad LFD_IO_ZERO;
  uint groups_x LFD_IO_ZERO;  // glDispatchComputeIndirect reads these three
  uint groups_y LFD_IO_ZERO;
  uint groups_z LFD_IO_ZERO;
  uint pad2 LFD_IO_ZERO;
};

LFD_IO_END

#endif
