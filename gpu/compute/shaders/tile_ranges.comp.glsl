// The per-slot ranges (gpu/compute/gl_tile_keys.hpp): over the sorted keys, where a slot's run starts and
// ends; each run's first key lists its slot for the indirect dispatch of the non-empty slots.
// The ranges are cleared to (0, 0) and the work count to 0 before the pass. count_from_state: the
// keys are min(state.keys, key_count) (GlTileKeys::sort_and_find_ranges_to_capacity: the total
// stays on the GPU, key_count is the capacity).
#include "gpu/compute/shaders/tile_io.h"

layout(local_size_x = kTileRangesGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"
layout(std430, binding = kTileKeysBinding) readonly buffer Keys { uint keys[]; };
layout(std430, binding = kTileRangesBinding) writeonly buffer Ranges { uvec2 ranges[]; };
layout(std430, binding = kTileWorkBinding) writeonly buffer Work { uint work[]; };
layout(std430, binding = kTileStateBinding) buffer State { TileState state; };
uniform uint key_count;
uniform bool count_from_state;

void main() {
  uint i = flat_invocation_index();
  uint count = count_from_state ? min(state.keys, key_count) : key_count;
  if (i >= count) return;
  uint slot = keys[i];
  if (i == 0u || keys[i - 1u] != slot) {
    ranges[slot].x = i;
    work[atomicAdd(state.work_count, 1u)] = slot;
  }
  if (i + 1u == count || keys[i + 1u] != slot) ranges[slot].y = i + 1u;
}
