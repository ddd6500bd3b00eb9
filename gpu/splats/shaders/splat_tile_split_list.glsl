// The split list's buffer (splat_tile_io.h TileSplitList; docs/gpu.md "Balancing"): its header,
// kTileSplatMaxParts split slots (slot, first key, end key, first part), then the parts (split
// slot, part). #included by splat_tile_split (which writes it), splat_tile_composite (SPLIT_PART
// 1) and splat_tile_merge, each defining SPLIT_LIST_ACCESS (readonly, or empty) first.
#include "gpu/splats/shaders/splat_tile_io.h"

layout(std430, binding = kTileSplatSplitBinding) SPLIT_LIST_ACCESS buffer Split {
  TileSplitList split;
  uvec4 split_slots[kTileSplatMaxParts];
  uvec2 split_parts[];
};
