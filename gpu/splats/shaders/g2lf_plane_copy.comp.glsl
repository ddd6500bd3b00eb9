// G2LF planes through float accumulation, pass 2, per batch (dispatched indirectly by pass 1):
// the batch's splats as a list of their own (instance i = sorted splat first + i) with their
// layer in the accumulation array, and the batch's indirect draw.
#include "gpu/splats/shaders/frame_io.h"

layout(local_size_x = kPlaneCopyGroupSize) in;

layout(std430, binding = kPlaneBatchesBinding) readonly buffer Batches { PlaneBatch batches[]; };
layout(std430, binding = kPlaneBatchDrawBinding) writeonly buffer Draw { uint draw_count; uint draw_instances; uint draw_first; uint draw_base; };
layout(std430, binding = kSplatValuesBinding) readonly buffer SortedIds { uint sorted_ids[]; };
layout(std430, binding = kSplatLayersBinding) readonly buffer Layers { uint layers[]; };
layout(std430, binding = kPlaneBatchIdsBinding) writeonly buffer BatchIds { uint batch_ids[]; };
layout(std430, binding = kPlaneBatchLayersBinding) writeonly buffer BatchLayers { uint batch_layers_of[]; };

uniform uint batch;
uniform uint batch_layers;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  const PlaneBatch b = batches[batch];
  if (i == 0u) {
    draw_count = 4u;
    draw_instances = b.count;
    draw_first = 0u;
    draw_base = 0u;
  }
  if (i >= b.count) return;
  batch_ids[i] = sorted_ids[b.first + i];
  batch_layers_of[i] = layers[b.first + i] - batch * batch_layers;
}
