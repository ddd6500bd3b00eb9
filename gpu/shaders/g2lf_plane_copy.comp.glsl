// G2LF planes through float accumulation, pass 2, per batch (dispatched indirectly by pass 1):
// the batch's splats as a list of their own (instance i = sorted splat first + i) with their
// layer in the accumulation array, and the batch's indirect draw.
layout(local_size_x = 256) in;

struct Batch {
  uint groups_x, groups_y, groups_z;
  uint first;
  uint count;
  uint pad0, pad1, pad2;
};
layout(std430, binding = 11) readonly buffer Batches { Batch batches[]; };
layout(std430, binding = 12) writeonly buffer Draw { uint draw_count; uint draw_instances; uint draw_first; uint draw_base; };
layout(std430, binding = 6) readonly buffer SortedIds { uint sorted_ids[]; };
layout(std430, binding = 8) readonly buffer Layers { uint layers[]; };
layout(std430, binding = 13) writeonly buffer BatchIds { uint batch_ids[]; };
layout(std430, binding = 14) writeonly buffer BatchLayers { uint batch_layers_of[]; };

uniform uint batch;
uniform uint batch_layers;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  const Batch b = batches[batch];
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
