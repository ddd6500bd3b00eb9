// Which image an item's keys go to (gpu/splats/gl_splat_tile_raster.hpp), for the key passes
// (splat_tile_keys.comp.glsl, splat_tile_huge.comp.glsl): PLANES 0, the view of entry
// view * gaussian_count + i; PLANES 1, the item's plane from the binning's layers.
#include "gpu/splats/shaders/splat_tile_io.h"

#if PLANES
layout(std430, binding = kTileSplatLayersBinding) readonly buffer Layers { uint layers[]; };
uint item_image(uint item, uint entry) { return layers[item]; }
#else
uniform uint gaussian_count;
uint item_image(uint item, uint entry) { return entry / gaussian_count; }
#endif

// The first slot of the item's image: slots are image * tiles + tile_y * tiles_x + tile_x.
uint item_first_slot(uint item, uint entry, ivec2 tile_grid) {
  return item_image(item, entry) * uint(tile_grid.x * tile_grid.y);
}
