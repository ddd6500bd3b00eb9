// A voxel's pixel footprint in one image (the GLSL twin of voxel/voxel_rasterizer.cpp's tile_rect
// before it is cut into tiles), shared by the raster pipeline's quads (voxel_raster.vert.glsl) and
// the compute tile rasterizer's keys (voxel_tile_keys.comp.glsl): every pixel whose centre ray can
// meet the box. The projected corners' bounding box, a pixel wider for rounding; the whole image
// when a corner lies behind the camera plane (the slab test sorts out the rays); empty when all 8
// do. Returns (first x, first y, last x, last y) in pixels, row 0 = top; empty: first > last.

ivec4 voxel_footprint(vec4 box, mat3 world_to_camera, vec3 camera_position, vec2 tan_half_fov, vec2 shift_ndc,
                      ivec2 image_size) {
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  int behind = 0;
  for (int c = 0; c < 8; ++c) {
    vec3 corner = box.xyz + box.w * vec3(float((c >> 2) & 1), float((c >> 1) & 1), float(c & 1));
    vec3 p = world_to_camera * (corner - camera_position);
    if (p.z <= 1e-6) {
      ++behind;
      continue;
    }
    // Pixel coordinates with centres at integers, row 0 = top (render::Camera::project_px).
    vec2 ndc = p.xy / (p.z * tan_half_fov) + shift_ndc;
    vec2 px = ((ndc + 1.0) * vec2(image_size) - 1.0) * 0.5;
    lo = min(lo, px);
    hi = max(hi, px);
  }
  ivec2 first = ivec2(0), last = image_size - 1;
  if (behind == 8) return ivec4(1, 1, 0, 0);
  if (behind == 0) {
    // Clamped as floats first: a huge extent must not overflow the conversion to int.
    vec2 limit_lo = vec2(-1.0), limit_hi = vec2(image_size);
    first = max(first, ivec2(clamp(floor(lo) - 1.0, limit_lo, limit_hi)));
    last = min(last, ivec2(clamp(ceil(hi) + 1.0, limit_lo, limit_hi)));
  }
  return ivec4(first, last);
}
