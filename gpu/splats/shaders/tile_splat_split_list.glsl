// The split list's buffer (tile_splat_io.h TileSplitList; docs/gpu.md "Balancing"): its header,
// kTileSplatMaxParts split slots (slot, first key, end key, first part), then the parts (split
// slot, part). #included by tile_splat_split (which writes it), tile_splat_composite (SPLIT_PART
// 1) and tile_splat_merge, each defining SPLIT_LIST_ACCESS (readonly, or empty) first.
#include "gpu/splats/shaders/tile_splat_io.h"

layout(std430, binding = kTileSplatSplitBinding) SPLIT_LIST_ACCESS buffer Split {
  TileSplitList split;
  uvec4 split_slots[kTileSplatMaxParts];
  uvec2 split_parts[];
};
