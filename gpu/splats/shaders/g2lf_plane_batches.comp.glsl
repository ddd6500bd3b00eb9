// G2LF planes through float accumulation (gpu/splats/gl_plane_raster.hpp), pass 1, one invocation per
// batch of `batch_layers` planes: the batch's splats are the sorted run from the first splat of
// its first plane to the first splat past its last plane (plane_count's entry holds the binned
// count, so the last batch ends there). Writes the run and the copy pass's indirect dispatch
// (at least one group, so the copy always writes the batch's draw command).
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/planes/shaders/plane_table.glsl"

layout(local_size_x = kPlaneBatchesGroupSize) in;

layout(std430, binding = kPlaneBatchesBinding) writeonly buffer Batches { PlaneBatch batches[]; };

uniform uint batch_count;
uniform uint batch_layers;

void main() {
  const uint b = gl_GlobalInvocationID.x;
  if (b >= batch_count) return;
  const uint count = table.plane_count;
  const uint first = plane[min(b * batch_layers, count)].begin;
  const uint last = plane[min((b + 1u) * batch_layers, count)].begin;
  const uint n = last - first;
  batches[b] = PlaneBatch(max(1u, (n + kPlaneCopyGroupSize - 1u) / kPlaneCopyGroupSize), 1u, 1u, first, n, 0u, 0u, 0u);
}
