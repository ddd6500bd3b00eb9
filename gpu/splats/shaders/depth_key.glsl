// Depth <-> radix-sort key of the depth binning (gpu/splats/gl_depth_binning.hpp), one definition for
// the passes that write keys and those that read depths back from the sorted keys.
//   SIGNED_DEPTH_KEYS 0: the depth's float bits. G2LF bins Gaussians whose depth is > 0.2, and
//     positive floats order as their bits.
//   SIGNED_DEPTH_KEYS 1: the order-preserving map of any float (sign bit flipped for positives,
//     all bits for negatives). V2LF bins voxels with any corner in front of the camera, so a
//     centre may lie behind it (a negative depth); -0 is keyed as +0 (the CPU's sort sees them
//     equal and orders by index).
// Culled primitives get 0xFFFFFFFF in both, after every depth.
#ifndef SIGNED_DEPTH_KEYS
#define SIGNED_DEPTH_KEYS 0
#endif

uint depth_key(float depth) {
#if SIGNED_DEPTH_KEYS
  const uint bits = floatBitsToUint(depth == 0.0 ? 0.0 : depth);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
#else
  return floatBitsToUint(depth);
#endif
}

float key_depth(uint key) {
#if SIGNED_DEPTH_KEYS
  return uintBitsToFloat((key & 0x80000000u) != 0u ? key ^ 0x80000000u : ~key);
#else
  return uintBitsToFloat(key);
#endif
}
