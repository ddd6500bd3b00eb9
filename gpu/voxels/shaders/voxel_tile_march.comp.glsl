// The voxel tile rasterizer's ray marching (gpu/voxels/gl_voxel_tile_raster.hpp): SVRaster's forward
// pass per tile, one work group a non-empty (run, tile) slot (slot = (plane * run_count + r) *
// tiles + tile; run r's octant and image in runs[r], VoxelTileRange), one invocation a pixel of
// the run's image. The slot's voxels, front to back in the octant's order, are loaded
// kTilePixels at a time into shared memory (box, densities and the SH colour seen from the
// image's sh_origin, once per voxel and tile), then every pixel whose ray takes the slot's octant
// composites the batch with the CPU's rules (gpu/voxels/shaders/voxel_ray.glsl;
// voxel/voxel_rasterizer.cpp): skip alpha < 1e-5, C += c alpha T, T *= 1 - alpha, stop once
// T < 1e-4 (what the raster pipeline's blending cannot do). A batch starts only while a pixel of
// the group is open. The result is composited over the target's (C, T) (rgba32f; image i's cell
// at viewport_origin + (i % target_cols, i / target_cols) * image_size, rows bottom-up):
// C + T_in C, T_in T. Pixels of another octant belong to another slot's group, so no two groups
// write the same texel. slot_run 0: the groups take the work list (the non-empty slots);
// slot_run > 0: group g takes slot slot_base + g, g < slot_run (one V2LF plane's run of slots;
// empty ones return at once). A pass whose keys outgrew the capacity (state.keys over key_capacity:
// keys were left out) marches nothing; it is drawn again after the frame (GlKeyCapacity), over
// the target as it was.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/sh_color.glsl"
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/compute/shaders/tile_batch.glsl"
#include "gpu/voxels/shaders/voxel_ray.glsl"
#include "gpu/voxels/shaders/voxel_tile_io.h"
#include "gpu/voxels/shaders/voxel_tile_view.glsl"

layout(local_size_x = kTileSide, local_size_y = kTileSide) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kVoxelBoxesBinding) readonly buffer Boxes { vec4 boxes[]; };
layout(std430, binding = kVoxelDensitiesBinding) readonly buffer Densities { vec4 densities[]; };
layout(std430, binding = kTileValuesBinding) readonly buffer Values { uint values[]; };
layout(std430, binding = kTileRangesBinding) readonly buffer Ranges { uvec2 ranges[]; };
layout(std430, binding = kTileWorkBinding) readonly buffer Work { uint work[]; };
layout(std430, binding = kTileStateBinding) readonly buffer State { TileState state; };
layout(rgba32f, binding = kVoxelTileTargetImage) uniform image2D target;

uniform ivec2 viewport_origin;
uniform int target_cols;  // images a row of the target holds
uniform int samples_per_voxel;
uniform uint slot_base;
uniform uint slot_run;
uniform uint key_capacity;  // the keys the buffers held (GlTileKeys::scan_to_capacity)

shared vec4 batch_box[kTilePixels];
shared vec4 batch_c0123[kTilePixels];
shared vec4 batch_c4567[kTilePixels];
shared vec3 batch_color[kTilePixels];

void main() {
  uint group = flat_group_index();
  if (state.keys > key_capacity) return;  // the same for every group
  uint slot;
  if (slot_run > 0u) {
    if (group >= slot_run) return;
    slot = slot_base + group;
  } else {
    if (group >= state.work_count) return;
    slot = work[group];
  }
  uvec2 range = ranges[slot];
  if (range.x == range.y) return;  // the same for the whole group
  uint tiles = uint(tile_grid.x * tile_grid.y);
  VoxelTileRange run = runs[(slot / tiles) % uint(run_count)];
  VoxelView view = voxel_view(run.image);
  int octant = int(run.octant);
  uint tile = slot % tiles;
  ivec2 pixel = ivec2(int(tile % uint(tile_grid.x)) * int(kTileSide) + int(gl_LocalInvocationID.x),
                      int(tile / uint(tile_grid.x)) * int(kTileSide) + int(gl_LocalInvocationID.y));
  bool inside = pixel.x < image_size.x && pixel.y < image_size.y;
  vec3 d = voxel_pixel_ray(vec2(pixel), image_size, view.world_to_camera, view.tan_half_fov, view.shift_ndc);
  bool mine = inside && voxel_ray_octant(d) == octant;
  bool done = !mine;
  float T = 1.0;
  vec3 C = vec3(0.0);
  uint local = gl_LocalInvocationIndex;
  for (uint base = range.x; base < range.y; base += kTilePixels) {
    tile_batch_vote(done);
    if (base + local < range.y) {
      uint voxel = values[base + local];
      vec4 box = boxes[voxel];
      batch_box[local] = box;
      batch_c0123[local] = densities[2u * voxel];
      batch_c4567[local] = densities[2u * voxel + 1u];
      batch_color[local] = sh_color(voxel, normalize(box.xyz + 0.5 * box.w - view.sh_origin));
    }
    if (!tile_batch_any_open()) break;  // every pixel is done: the same for the whole group
    uint n = min(kTilePixels, range.y - base);
    for (uint s = 0u; s < n && !done; ++s) {
      float alpha = voxel_alpha(batch_box[s], batch_c0123[s], batch_c4567[s], view.position, d, samples_per_voxel);
      if (alpha < kVoxelMinAlpha) continue;
      C += T * alpha * batch_color[s];
      T *= 1.0 - alpha;
      if (T < kVoxelMinTransmittance) done = true;
    }
  }
  if (!mine) return;
  ivec2 cell = ivec2(int(run.image) % target_cols, int(run.image) / target_cols);
  ivec2 texel = viewport_origin + cell * image_size + ivec2(pixel.x, image_size.y - 1 - pixel.y);
  vec4 before = imageLoad(target, texel);  // (C, T) of what lies in front (a cleared target: (0, 0, 0, 1))
  imageStore(target, texel, vec4(before.rgb + before.a * C, before.a * T));
}
