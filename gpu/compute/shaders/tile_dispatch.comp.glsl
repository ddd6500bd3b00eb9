// One invocation turns a count on the GPU into a DispatchIndirectCommand of one work group per
// counted thing, spread over y beyond the 65535 groups of one dimension as gpu/gl/gl_work_groups.hpp
// spreads them on the CPU (gpu/compute/gl_tile_keys.hpp: the non-empty slots; the splats' huge
// items). Shaders index groups with flat_group_index() (gpu/gl/shaders/flat_group.glsl) and skip
// those past the count.
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/gl/shaders/work_groups_io.h"

layout(local_size_x = kTileDispatchGroupSize) in;
layout(std430, binding = kTileStateBinding) buffer Target { uint words[]; };
uniform uint count_word;     // the count's index in words
uniform uint dispatch_word;  // where groups x, y, z go

void main() {
  uint count = words[count_word];
  words[dispatch_word] = min(count, kMaxWorkGroupsX);
  words[dispatch_word + 1u] = count == 0u ? 0u : (count + kMaxWorkGroupsX - 1u) / kMaxWorkGroupsX;
  words[dispatch_word + 2u] = 1u;
}
