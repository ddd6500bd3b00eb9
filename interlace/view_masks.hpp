#pragma once
// Per-view direct (docs/rendering.md "Per-view direct: the baseline"): which pixels of each quilt
// view the panel shows at all. The interlacer (interlacer.hpp) gives every panel subpixel a view
// (two when blending linearly) and a bilinear lookup of four texels in that view's tile; a view
// pixel no subpixel reads never reaches the panel, so a per-view renderer may skip it. The masks
// are that lookup run backwards (Interlacer::sample_for and tile_texels: the one relation), so
// rendering only the masked-in pixels, then interlacing, gives the panel of the full views bit for
// bit (tests/interlace/view_masks_test.cpp).
#include <cstdint>
#include <vector>

#include "interlace/interlacer.hpp"

namespace lfd::interlace {

struct ViewMasks {
  int width = 0, height = 0;  // a view's size (the quilt layout's tile)
  // Per view, width x height bytes, row 0 = top (the view image's rows): 1 where the panel reads.
  std::vector<std::vector<uint8_t>> masks;

  // The fraction of all views' pixels that are masked in.
  double fraction_in() const;
};

// Every texel the interlacer reads for the display (all three channels, both views of a linear
// blend where the second has a non-zero weight; all four texels of the bilinear footprint, even
// at zero weight, so the interlaced panel is bit-identical).
ViewMasks view_masks(const Interlacer& interlacer);

}  // namespace lfd::interlace
