// The view uniforms of the voxel tile rasterizer's passes (gpu/gl_voxel_tile_raster.hpp) and the
// octants a tile's rays take (the world direction is linear in the pixel position, so the tile's
// corner pixels bound its signs per axis, as gpu::octants_in_view does per image).
uniform mat3 world_to_camera;
uniform vec3 camera_position;
uniform vec2 tan_half_fov;
uniform vec2 shift_ndc;
uniform ivec2 image_size;
uniform ivec2 tile_grid;

uint tile_octants(ivec2 tile) {
  ivec2 first = tile * int(kTileSide), last = min(first + int(kTileSide) - 1, image_size - 1);
  uint negative = 0u, positive = 0u;  // per axis (bit 2 = x, 1 = y, 0 = z): a corner ray has that sign
  for (int c = 0; c < 4; ++c) {
    vec2 pixel = vec2((c & 1) != 0 ? last.x : first.x, (c & 2) != 0 ? last.y : first.y);
    vec2 ndc = (2.0 * pixel + 1.0) / vec2(image_size) - 1.0;
    vec3 d = transpose(world_to_camera) * vec3((ndc - shift_ndc) * tan_half_fov, 1.0);
    negative |= (d.x < 0.0 ? 4u : 0u) | (d.y < 0.0 ? 2u : 0u) | (d.z < 0.0 ? 1u : 0u);
    positive |= (d.x < 0.0 ? 0u : 4u) | (d.y < 0.0 ? 0u : 2u) | (d.z < 0.0 ? 0u : 1u);
  }
  uint mask = 0u;
  for (uint o = 0u; o < 8u; ++o) {
    uint wants_negative = o, wants_positive = ~o & 7u;
    if ((wants_negative & ~negative) == 0u && (wants_positive & ~positive) == 0u) mask |= 1u << o;
  }
  return mask;
}
