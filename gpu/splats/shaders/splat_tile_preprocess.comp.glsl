// The compute tile rasterizer's preprocess (gpu/splats/gl_splat_tile_raster.hpp): every Gaussian in every view
// in one dispatch (z = the view), each projected exactly as the per-view preprocess does
// (splat_project.glsl), into the record of entry view * gaussian_count + i with its depth key
// (0xFFFFFFFF: culled) for the depth sort of all entries.
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/splat_record.glsl"
#include "gpu/splats/shaders/splat_tile_io.h"

layout(local_size_x = kSplatPreprocessGroupSize) in;
#include "gpu/gl/shaders/flat_group.glsl"

layout(std430, binding = kScenePositionsBinding) readonly buffer Positions { vec4 positions[]; };  // xyz, opacity
layout(std430, binding = kSceneScalesBinding) readonly buffer Scales { vec4 scales[]; };
layout(std430, binding = kSceneRotationsBinding) readonly buffer Rotations { vec4 rotations[]; };  // w, x, y, z
layout(std430, binding = kSplatRecordsBinding) writeonly buffer Records { SplatRecord records[]; };
layout(std430, binding = kTileSplatEntryKeysBinding) writeonly buffer Keys { uint keys[]; };
layout(std430, binding = kTileSplatEntriesBinding) writeonly buffer Entries { uint entries[]; };
layout(std430, binding = kTileSplatViewsBinding) readonly buffer Views { TileViewCamera views[]; };

uniform uint gaussian_count;
uniform ivec2 image_size;
uniform ivec2 tile_grid;
uniform float dilation_px2;
uniform float scale_modifier;

// The view's camera, set from its TileViewCamera before the projection reads it.
mat3 world_to_camera;
vec3 camera_position;
vec2 tan_half_fov;
vec2 focal_px;
vec2 shift_ndc;
vec3 sh_origin;

#include "gpu/splats/shaders/splat_project.glsl"

void main() {
  uint i = flat_invocation_index();
  if (i >= gaussian_count) return;
  uint view = gl_WorkGroupID.z;
  TileViewCamera c = views[view];
  world_to_camera = mat3(vec3(c.world_to_camera[0], c.world_to_camera[1], c.world_to_camera[2]),
                         vec3(c.world_to_camera[4], c.world_to_camera[5], c.world_to_camera[6]),
                         vec3(c.world_to_camera[8], c.world_to_camera[9], c.world_to_camera[10]));
  camera_position = vec3(c.position[0], c.position[1], c.position[2]);
  sh_origin = vec3(c.sh_origin[0], c.sh_origin[1], c.sh_origin[2]);
  tan_half_fov = vec2(c.tan_half_fov[0], c.tan_half_fov[1]);
  focal_px = vec2(c.focal_px[0], c.focal_px[1]);
  shift_ndc = vec2(c.shift_ndc[0], c.shift_ndc[1]);
  uint entry = view * gaussian_count + i;
  SplatRecord record;
  uint key;
  if (project_splat(i, record, key)) {
    records[entry] = record;
    keys[entry] = key;
  } else {
    keys[entry] = 0xFFFFFFFFu;
  }
  entries[entry] = entry;
}
