// The compute tile rasterizer's compositing (gpu/splats/gl_splat_tile_raster.hpp): the reference's renderCUDA
// (forward.cu; the CPU's render/blend.cpp), one work group a (image, tile) slot, one invocation a
// pixel. The slot's splats, front to back, are loaded kTilePixels at a time into shared memory
// (one each), then every pixel blends the batch with the reference's alpha rules
// (splat_tile_blend.glsl). A batch starts only while a pixel of the tile still blends (the
// reference's __syncthreads_count early stop).
//   SPLIT_PART 0: whole slots into the target (splat_tile_target.glsl). TARGET_ARRAY 0 (views):
//                 every slot is dispatched (empty tiles get the background); TARGET_ARRAY 1
//                 (planes): only the non-empty slots run (the work list), the planes are cleared
//                 to (0, 0, 0, 1). A split slot's range was emptied (splat_tile_split): it gets
//                 the background here and its pixels from splat_tile_merge after.
//   SPLIT_PART 1: one part of a split slot (docs/gpu.md "Balancing"): split_keys of its keys from
//                 T = 1, into the part's partial (C, T), T negated where the pixel stopped.
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
#if SPLIT_PART
#define SPLIT_LIST_ACCESS readonly
#include "gpu/splats/shaders/splat_tile_split_list.glsl"
layout(std430, binding = kTileSplatPartialsBinding) writeonly buffer Partials { vec4 partials[]; };
uniform uint split_keys;
#else
layout(std430, binding = kTileRangesBinding) readonly buffer Ranges { uvec2 ranges[]; };
#if TARGET_ARRAY
layout(std430, binding = kTileWorkBinding) readonly buffer Work { uint work[]; };
layout(std430, binding = kTileStateBinding) readonly buffer State { TileState state; };
#else
uniform uint slot_count;
#endif
#endif

shared vec2 batch_mean[kTilePixels];
shared vec4 batch_conic_opacity[kTilePixels];
shared vec3 batch_color[kTilePixels];
shared uint batch_alive;

void main() {
  uint group = flat_group_index();
#if SPLIT_PART
  if (group >= min(split.parts, kTileSplatMaxParts)) return;
  uvec2 part = split_parts[group];
  if (part.x == 0xFFFFFFFFu) return;  // handed out to a slot that did not fit
  uvec4 s = split_slots[part.x];
  uint slot = s.x;
  uint first = s.y + part.y * split_keys;
  uvec2 range = uvec2(first, min(s.z, first + split_keys));
#else
#if TARGET_ARRAY
  if (group >= state.work_count) return;
  uint slot = work[group];
#else
  if (group >= slot_count) return;
  uint slot = group;
#endif
  uvec2 range = ranges[slot];
#endif
  ivec2 pixel = slot_pixel(slot);
  bool inside = inside_image(pixel);
  bool done = !inside;
  vec2 pixf = vec2(pixel);
  float T = 1.0;
  vec3 C = vec3(0.0);
  uint local = gl_LocalInvocationIndex;
  for (uint base = range.x; base < range.y; base += kTilePixels) {
    barrier();  // the last batch is read, batch_alive too
    if (local == 0u) batch_alive = 0u;
    barrier();
    if (!done) batch_alive = 1u;
    if (base + local < range.y) {
      SplatRecord r = records[values[base + local]];
      batch_mean[local] = r.mean_depth_opacity.xy;
      batch_conic_opacity[local] = vec4(r.conic_radius.xyz, r.mean_depth_opacity.w);
      batch_color[local] = r.color.rgb;
    }
    barrier();
    if (batch_alive == 0u) break;  // every pixel is done: the same for the whole group
    uint n = min(kTilePixels, range.y - base);
    for (uint k = 0u; k < n && !done; ++k)
      done = !blend_splat(batch_mean[k], batch_conic_opacity[k], batch_color[k], pixf, C, T);
  }
#if SPLIT_PART
  partials[(s.w + part.y) * kTilePixels + local] = vec4(C, done && inside ? -T : T);
#else
  if (!inside) return;
  write_pixel(slot_image(slot), pixel, C, T);
#endif
}
