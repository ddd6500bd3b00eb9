#pragma once
// Stage 3 of the 3DGS forward pass, per pixel (forward.cu renderCUDA;
// docs/rendering.md "The CPU reference rasterizer"): front-to-back alpha compositing of the tile's
// sorted list, C = sum_i c_i a_i prod_{j<i} (1 - a_j) with a_i = min(0.99, o_i exp(power)),
// skipping power > 0 and a_i < 1/255 and stopping before T falls below 1e-4, exactly as the
// CUDA thread does. The final transmittance is kept beside the colour: G2LF's sweeping planes
// are this image with a zero background (premultiplied colour + T).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/preprocess.hpp"
#include "render/tile_binning.hpp"

namespace lfd::render {

// Colour (row 0 = top, RGB interleaved, not clamped: out = C + T bg) and the final
// transmittance T per pixel.
//
// `pixel_mask` (width x height, row 0 = top; empty: every pixel): only pixels with a non-zero
// entry are blended; the others are left at the background with T = 1, and a tile with none is
// skipped whole. A blended pixel's sequence of operations is the unmasked one, so its colour is
// bit-identical (the per-view direct baseline, interlace/view_masks.hpp; docs/rendering.md
// "Per-view direct").
struct RasterImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
  std::vector<float> transmittance;
};
RasterImage blend(const std::vector<ProjectedGaussian>& projected, const TileBins& bins, int width,
                  int height, const glm::vec3& background, std::span<const uint8_t> pixel_mask = {});

}  // namespace lfd::render
