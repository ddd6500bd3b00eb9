// The split slots' merge (gpu/splats/gl_splat_tile_raster.hpp; docs/gpu.md "Balancing"): one work group a split
// slot, one invocation a pixel, its parts' partial (C_i, T_i) combined front to back,
// C = C_0 + T_0 C_1 + T_0 T_1 C_2 ..., T = T_0 T_1 ... . The reference stops a pixel before T
// would fall under 1e-4; a part composited from T = 1 does not know where that happens, so the
// part where it does (the part stopped the pixel itself, or T T_i < 1e-4) is replayed for that
// pixel from the true T with the reference's rules, and the pixel ends there: the image is the
// whole slot's, up to the rounding of the products.
#include "gpu/splats/shaders/splat_record.glsl"
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/splats/shaders/splat_tile_io.h"
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/splat_tile_blend.glsl"
#include "gpu/splats/shaders/splat_tile_target.glsl"

layout(local_size_x = kTileSide, local_size_y = kTileSide) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kSplatRecordsBinding) readonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kTileValuesBinding) readonly buffer Values { uint values[]; };
#define SPLIT_LIST_ACCESS readonly
#include "gpu/splats/shaders/splat_tile_split_list.glsl"
layout(std430, binding = kTileSplatPartialsBinding) readonly buffer Partials { vec4 partials[]; };
uniform uint split_keys;

void main() {
  uint group = flat_group_index();
  if (group >= split.slots) return;
  uvec4 s = split_slots[group];
  ivec2 pixel = slot_pixel(s.x);
  if (!inside_image(pixel)) return;
  vec2 pixf = vec2(pixel);
  vec3 C = vec3(0.0);
  float T = 1.0;
  uint parts = (s.z - s.y + split_keys - 1u) / split_keys;
  for (uint p = 0u; p < parts; ++p) {
    vec4 q = partials[(s.w + p) * kTilePixels + gl_LocalInvocationIndex];
    float part_T = abs(q.w);
    if (q.w >= 0.0 && T * part_T >= 0.0001) {
      C += T * q.rgb;
      T *= part_T;
      continue;
    }
    // The stop falls in this part: replay it from the true T.
    bool stopped = false;
    uint first = s.y + p * split_keys, end = min(s.z, first + split_keys);
    for (uint k = first; k < end && !stopped; ++k) {
      SplatRecord r = records[values[k]];
      stopped = !blend_splat(r.mean_depth_opacity.xy, vec4(r.conic_radius.xyz, r.mean_depth_opacity.w), r.color.rgb,
                             pixf, C, T);
    }
    if (stopped) break;
  }
  write_pixel(slot_image(s.x), pixel, C, T);
}
