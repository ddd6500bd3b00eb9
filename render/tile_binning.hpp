#pragma once
// Stage 2 of the 3DGS forward pass, per tile (rasterizer_impl.cu duplicateWithKeys, the radix sort
// of (tile << 32 | depth) keys and identifyTileRanges; docs/rendering.md "The CPU reference
// rasterizer"): every projected Gaussian is listed once in each 16x16 tile its rectangle touches,
// and each tile's list is ordered front to back by view-space depth, ties kept in Gaussian order as
// the reference's stable sort does. Blending then walks one short list per tile instead of every
// Gaussian per pixel.
#include <cstdint>
#include <vector>

#include "render/preprocess.hpp"

namespace lfd::render {

// Per tile (row-major over the tile grid), the indices into `projected` front to back.
struct TileBins {
  int tiles_x = 0, tiles_y = 0;
  std::vector<uint32_t> range_begin;  // tiles_x * tiles_y + 1 offsets into `ids`
  std::vector<uint32_t> ids;
};
TileBins bin_and_sort(const std::vector<ProjectedGaussian>& projected, int width, int height);

}  // namespace lfd::render
