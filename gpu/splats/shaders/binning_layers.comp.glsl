// G2LF depth binning, pass 4: the plane (array layer) of every binned splat in sorted order, for
// the layered raster's gl_Layer: the last plane whose first splat is not after it.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/planes/shaders/plane_table.glsl"

layout(local_size_x = kBinningLayersGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kSplatLayersBinding) writeonly buffer Layers { uint layers[]; };

void main() {
  const uint i = flat_invocation_index();
  if (i >= table.splats_binned) return;
  uint lo = 0u, hi = table.plane_count;  // planes with begin <= i: [0, lo)
  while (lo < hi) {
    const uint mid = (lo + hi) / 2u;
    if (plane[mid].begin <= i) lo = mid + 1u;
    else hi = mid;
  }
  layers[i] = lo - 1u;
}
