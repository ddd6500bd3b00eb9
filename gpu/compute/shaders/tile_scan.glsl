// The work group's exclusive prefix sum (gpu/compute/gl_tile_keys.hpp): every invocation of a
// kTileScanGroupSize group gives a value and gets the sum of the lower invocations' values, and
// the group's total. A Hillis-Steele scan in shared memory (log2 256 = 8 steps); #included by the
// tile scan passes.
#include "gpu/compute/shaders/tile_io.h"

shared uint scan_values[kTileScanGroupSize];

uint group_exclusive_scan(uint value, out uint total) {
  uint i = gl_LocalInvocationIndex;
  scan_values[i] = value;
  barrier();
  for (uint step = 1u; step < kTileScanGroupSize; step <<= 1u) {
    uint add = i >= step ? scan_values[i - step] : 0u;
    barrier();
    scan_values[i] += add;
    barrier();
  }
  total = scan_values[kTileScanGroupSize - 1u];
  uint inclusive = scan_values[i];
  barrier();  // the array is free for the next call
  return inclusive - value;
}
