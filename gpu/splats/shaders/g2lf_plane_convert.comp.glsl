// G2LF planes through float accumulation, pass 3, per batch: each accumulated layer rounded
// into its plane as render::render_sweeping_planes stores it (RGBA8: round(clamp(v, 0, 1) 255),
// written as an exact k/255 so the unorm conversion cannot round differently; RGBA16F: the
// conversion's rounding), and the accumulation texel reset to empty (C = 0, T = 1) for the next
// batch. Layers past the frame's plane count were not drawn into and are left alone.
// Defines: PLANE_FORMAT (rgba8 | rgba16f), QUANTIZE_U8 0|1.
#include "gpu/planes/shaders/plane_io.h"
#include "gpu/planes/shaders/plane_table.glsl"

layout(local_size_x = kPlaneGroupWidth, local_size_y = kPlaneGroupHeight) in;

layout(rgba32f, binding = kPlaneAccumulationImage) uniform image2DArray accumulation;
layout(PLANE_FORMAT, binding = kPlaneTexelsImage) uniform writeonly image2DArray planes;
// PlaneTable (plane_table.glsl): table.plane_count, table.splats_binned, plane[k].

uniform uint batch;
uniform uint batch_layers;
uniform ivec2 plane_size;

void main() {
  const ivec3 p = ivec3(gl_GlobalInvocationID);
  const uint plane = batch * batch_layers + uint(p.z);
  if (p.x >= plane_size.x || p.y >= plane_size.y || plane >= table.plane_count) return;
  vec4 v = imageLoad(accumulation, p);
#if QUANTIZE_U8
  precise vec4 q = floor(clamp(v, 0.0, 1.0) * 255.0 + 0.5);
  v = q / 255.0;
#endif
  imageStore(planes, ivec3(p.xy, int(plane)), v);
  imageStore(accumulation, p, vec4(0.0, 0.0, 0.0, 1.0));
}
