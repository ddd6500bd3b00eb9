// The split of hot tiles (gpu/splats/gl_splat_tile_raster.hpp; docs/gpu.md "Balancing"), one invocation a
// non-empty slot of the work list: a slot whose list holds more than split_keys keys gets
// ceil(keys / split_keys) parts of the split list (while they fit in kTileSplatMaxParts) and its
// range is emptied, so the whole-slot compositing skips it; splat_tile_composite (SPLIT_PART 1)
// composites the parts and splat_tile_merge combines them. The list's header and parts are
// cleared (parts to 0xFFFFFFFF) before the pass.
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/splats/shaders/splat_tile_io.h"

layout(local_size_x = kTileSplatSplitGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"
layout(std430, binding = kTileRangesBinding) buffer Ranges { uvec2 ranges[]; };
layout(std430, binding = kTileWorkBinding) readonly buffer Work { uint work[]; };
layout(std430, binding = kTileStateBinding) readonly buffer State { TileState state; };
#define SPLIT_LIST_ACCESS
#include "gpu/splats/shaders/splat_tile_split_list.glsl"
uniform uint split_keys;

void main() {
  uint i = flat_invocation_index();
  if (i >= state.work_count) return;
  uint slot = work[i];
  uvec2 range = ranges[slot];
  uint keys = range.y - range.x;
  if (keys <= split_keys) return;
  uint parts = (keys + split_keys - 1u) / split_keys;
  uint first_part = atomicAdd(split.parts, parts);
  if (first_part + parts > kTileSplatMaxParts) return;  // no room: composited whole (the same image)
  uint s = atomicAdd(split.slots, 1u);
  split_slots[s] = uvec4(slot, range.x, range.y, first_part);
  for (uint p = 0u; p < parts; ++p) split_parts[first_part + p] = uvec2(s, p);
  ranges[slot] = uvec2(0u);
}
