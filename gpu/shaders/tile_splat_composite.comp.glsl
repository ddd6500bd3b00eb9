// The compute tile rasterizer's compositing (gpu/gl_tile_splats.hpp): the reference's renderCUDA
// (forward.cu; the CPU's render/blend.cpp), one work group a (image, tile) slot, one invocation a
// pixel. The slot's splats, front to back, are loaded kTilePixels at a time into shared memory
// (one each), then every pixel blends the batch with the reference's alpha rules: skip
// power > 0 and alpha < 1/255, alpha clamped at 0.99, stop before T would fall under 1e-4. A
// batch starts only while a pixel of the tile still blends (the reference's
// __syncthreads_count early stop).
//   TARGET_ARRAY 0: views into a quilt (image = view; its cell at (view % cols, view / cols),
//                   bottom-up, cropped to the cell), C + T background and alpha T or 1;
//                   every slot is dispatched (empty tiles get the background).
//   TARGET_ARRAY 1: planes (image = plane = layer), (C, T) with a zero background; only the
//                   non-empty slots run (the work list), the planes are cleared to (0, 0, 0, 1).
//   TARGET_FORMAT: the target's image format (rgba32f, rgba16f, rgba8); QUANTIZE_U8 rounds as
//                  the CPU stores 8-bit planes.
#include "gpu/shaders/splat_record.glsl"
#include "gpu/shaders/tile_io.h"
#include "gpu/shaders/tile_splat_io.h"
#include "gpu/shaders/frame_io.h"

layout(local_size_x = kTileSide, local_size_y = kTileSide) in;

layout(std430, binding = kSplatRecordsBinding) readonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kTileValuesBinding) readonly buffer Values { uint values[]; };
layout(std430, binding = kTileRangesBinding) readonly buffer Ranges { uvec2 ranges[]; };
#if TARGET_ARRAY
layout(std430, binding = kTileWorkBinding) readonly buffer Work { uint work[]; };
layout(std430, binding = kTileStateBinding) readonly buffer State { TileState state; };
layout(TARGET_FORMAT, binding = kTileSplatTargetImage) uniform writeonly image2DArray target;
#else
layout(TARGET_FORMAT, binding = kTileSplatTargetImage) uniform writeonly image2D target;
uniform uint slot_count;
uniform uint first_view;     // the pass's first view (the image index counts from it)
uniform int cols;            // quilt columns
uniform ivec2 cell_size;     // a quilt cell (a view larger than it is cropped at its right and bottom)
uniform vec3 background;
uniform int keep_transmittance;  // alpha = T (one view's target) or 1 (a quilt)
#endif
uniform ivec2 image_size;
uniform ivec2 tile_grid;

shared vec2 batch_mean[kTilePixels];
shared vec4 batch_conic_opacity[kTilePixels];
shared vec3 batch_color[kTilePixels];
shared uint batch_alive;

void main() {
  uint group = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
#if TARGET_ARRAY
  if (group >= state.work_count) return;
  uint slot = work[group];
#else
  if (group >= slot_count) return;
  uint slot = group;
#endif
  uint tiles = uint(tile_grid.x * tile_grid.y);
  uint image = slot / tiles, tile = slot % tiles;
  ivec2 pixel = ivec2(int(tile % uint(tile_grid.x)) * int(kTileSide) + int(gl_LocalInvocationID.x),
                      int(tile / uint(tile_grid.x)) * int(kTileSide) + int(gl_LocalInvocationID.y));
  bool inside = pixel.x < image_size.x && pixel.y < image_size.y;
  bool done = !inside;
  vec2 pixf = vec2(pixel);
  float T = 1.0;
  vec3 C = vec3(0.0);
  uvec2 range = ranges[slot];
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
    for (uint s = 0u; s < n && !done; ++s) {
      vec2 d = batch_mean[s] - pixf;
      vec4 co = batch_conic_opacity[s];
      float power = -0.5 * (co.x * d.x * d.x + co.z * d.y * d.y) - co.y * d.x * d.y;
      if (power > 0.0) continue;
      float alpha = min(0.99, co.w * exp(power));
      if (alpha < 1.0 / 255.0) continue;
      float test_T = T * (1.0 - alpha);
      if (test_T < 0.0001) {
        done = true;
        continue;
      }
      float w = alpha * T;
      C += batch_color[s] * w;
      T = test_T;
    }
  }
  if (!inside) return;
#if TARGET_ARRAY
  vec4 value = vec4(C, T);
#if QUANTIZE_U8
  value = round(clamp(value, 0.0, 1.0) * 255.0) / 255.0;
#endif
  imageStore(target, ivec3(pixel.x, image_size.y - 1 - pixel.y, int(image)), value);
#else
  if (pixel.x >= cell_size.x || pixel.y >= cell_size.y) return;
  uint view = first_view + image;
  ivec2 texel = ivec2(int(view % uint(cols)) * cell_size.x + pixel.x,
                      int(view / uint(cols)) * cell_size.y + cell_size.y - 1 - pixel.y);
  imageStore(target, texel, vec4(C + T * background, keep_transmittance != 0 ? T : 1.0));
#endif
}
