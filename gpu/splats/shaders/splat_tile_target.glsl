// Where the compute tile rasterizer's compositing writes a slot's pixels (splat_tile_composite,
// splat_tile_merge; gpu/splats/gl_splat_tile_raster.hpp):
//   TARGET_ARRAY 0: views into a quilt (image = view; its cell at (view % cols, view / cols),
//                   bottom-up, cropped to the cell), C + T background and alpha T or 1.
//   TARGET_ARRAY 1: planes (image = plane = layer), (C, T) with a zero background.
//   TARGET_FORMAT: the target's image format (rgba32f, rgba16f, rgba8); QUANTIZE_U8 rounds as
//                  the CPU stores 8-bit planes.
#include "gpu/compute/shaders/tile_io.h"
#include "gpu/splats/shaders/splat_tile_io.h"

#if TARGET_ARRAY
layout(TARGET_FORMAT, binding = kTileSplatTargetImage) uniform writeonly image2DArray target;
#else
layout(TARGET_FORMAT, binding = kTileSplatTargetImage) uniform writeonly image2D target;
uniform uint first_view;     // the pass's first view (the image index counts from it)
uniform int cols;            // quilt columns
uniform ivec2 cell_size;     // a quilt cell (a view larger than it is cropped at its right and bottom)
uniform vec3 background;
uniform int keep_transmittance;  // alpha = T (one view's target) or 1 (a quilt)
#endif
uniform ivec2 image_size;
uniform ivec2 tile_grid;

// This invocation's pixel of `slot`'s tile (row 0 = top), and the slot's image.
ivec2 slot_pixel(uint slot) {
  uint tile = slot % uint(tile_grid.x * tile_grid.y);
  return ivec2(int(tile % uint(tile_grid.x)) * int(kTileSide) + int(gl_LocalInvocationID.x),
               int(tile / uint(tile_grid.x)) * int(kTileSide) + int(gl_LocalInvocationID.y));
}
uint slot_image(uint slot) { return slot / uint(tile_grid.x * tile_grid.y); }
bool inside_image(ivec2 pixel) { return pixel.x < image_size.x && pixel.y < image_size.y; }

void write_pixel(uint image, ivec2 pixel, vec3 C, float T) {
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
