// One invocation turns a count on the GPU into a DispatchIndirectCommand of one work group per
// counted thing, spread over y beyond the 65535 groups of one dimension (gpu/compute/gl_tile_keys.hpp:
// the non-empty slots; the splats' huge items). Shaders index groups as x + y * gl_NumWorkGroups.x
// and skip those past the count.
#include "gpu/compute/shaders/tile_io.h"

layout(local_size_x = kTileDispatchGroupSize) in;
layout(std430, binding = kTileStateBinding) buffer Target { uint words[]; };
uniform uint count_word;     // the count's index in words
uniform uint dispatch_word;  // where groups x, y, z go

void main() {
  uint count = words[count_word];
  words[dispatch_word] = min(count, 65535u);
  words[dispatch_word + 1u] = count == 0u ? 0u : (count + 65534u) / 65535u;
  words[dispatch_word + 2u] = 1u;
}
